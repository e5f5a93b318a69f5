// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/RecordSources.h"

#include <QFileInfo>

namespace kinstab::report {

namespace {

struct ShippedRecord {
    const char* file;
    const char* citation;
};

// From resources/records/SOURCES.md: the PEER NGA-West2 record, its station and component, the
// repository it was copied from and that repository's licence.
constexpr ShippedRecord kShipped[] = {
    {"RSN77_SFERN_PUL164.AT2",
     "1971 San Fernando earthquake, Pacoima Dam (upper left abutment), CDMG station 279, "
     "component 164°. PEER NGA-West2 database, record sequence number (RSN) 77, AT2 file "
     "RSN77_SFERN_PUL164.AT2, copied from NHERI-SimCenter/EE-UQ (BSD-2-Clause). Recorded by "
     "CDMG/CGS-CSMIP; PEER NGA terms of use apply."},
    {"RSN6_IMPVALL.I_I-ELC180.AT2",
     "1940 Imperial Valley earthquake, El Centro Array #9, component 180°. PEER NGA-West2 "
     "database, RSN 6, AT2 file RSN6_IMPVALL.I_I-ELC180.AT2, copied from NHERI-SimCenter/EE-UQ "
     "(BSD-2-Clause). PEER NGA terms of use apply."},
    {"RSN68_SFERN_PEL-UP.AT2",
     "1971 San Fernando earthquake, LA Hollywood Storage FF, vertical (UP) component. PEER "
     "NGA-West2 database, RSN 68, AT2 file RSN68_SFERN_PEL-UP.AT2, copied from "
     "jfayaz/Parse_NGAWEST2_GMs_to_AT2_-_Spectra_to_txt (MIT). PEER NGA terms of use apply."},
};

} // namespace

QString recordCitation(const Accelerogram& record, const QString& path) {
    const QString file = QFileInfo(path).fileName();
    for (const ShippedRecord& s : kShipped)
        if (file == QLatin1String(s.file)) return QString::fromUtf8(s.citation);
    QString c = QString::fromStdString(record.name);
    if (!record.station.empty()) c += ", station " + QString::fromStdString(record.station);
    if (!record.component.empty()) c += ", component " + QString::fromStdString(record.component);
    return c + QStringLiteral(". Accelerogram file %1 supplied by the engineer; its source and "
                              "terms of use are the engineer's to state.")
                   .arg(file);
}

} // namespace kinstab::report
