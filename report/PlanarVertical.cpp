// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/PlanarVertical.h"

#include "core/slab/VerticalRecord.h"

namespace kinstab::report {

QString defaultVerticalRecordPath() {
    return QString::fromUtf8(kRsn68UpSource); // also in the resources, for the record preview
}

QString defaultVerticalRecordNote() {
    return QObject::tr(
        "Vertical motion: 1971 San Fernando, LA Hollywood Storage FF, UP (NGA RSN68) stands in for "
        "the paper's Pacoima Dam vertical, which is not publicly available.");
}

QString verticalDescription(const PlanarSettings& s) {
    switch (s.vertical) {
    case VerticalSource::None:
        return QObject::tr("none (gravity only)");
    case VerticalSource::Rsn68Up:
        return defaultVerticalRecordNote();
    case VerticalSource::File:
        return QObject::tr("record file %1").arg(QString::fromStdString(s.verticalPath));
    }
    return {};
}

} // namespace kinstab::report
