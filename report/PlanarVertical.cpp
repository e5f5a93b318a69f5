// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/PlanarVertical.h"

#include "core/slab/VerticalRecord.h"

#include <QFileInfo>

namespace kinstab::ui {

QString defaultVerticalRecordPath() {
    return QString::fromUtf8(kRsn68UpSource); // also in the resources, for the record preview
}

QString defaultVerticalRecordNote() {
    return QObject::tr(
        "Vertical motion: 1971 San Fernando, LA Hollywood Storage FF, UP (NGA RSN68) stands in for "
        "the paper's Pacoima Dam vertical, which is not publicly available.");
}

std::optional<Accelerogram> readVerticalRecord(const PlanarSettings& s) {
    return loadVerticalRecord(s);
}

PlanarCase projectPlanarCase(const Slab1DCase& common, const PlanarSettings& s) {
    return planarCaseWithVertical(common, s);
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

QString planarSummary(const PlanarSettings& s) {
    const QString vertical = s.vertical == VerticalSource::None ? QObject::tr("none")
                             : s.vertical == VerticalSource::Rsn68Up
                                 ? QStringLiteral("RSN68 UP")
                                 : QFileInfo(QString::fromStdString(s.verticalPath)).fileName();
    return QObject::tr("planar (f_y = %1 Hz, A_y/A_x = %2, Θ = %3, %4, vertical %5)")
        .arg(s.fyHz)
        .arg(s.ayRatio)
        .arg(s.theta)
        .arg(QString::fromStdString(normalizationName(s.normalization)))
        .arg(vertical);
}

} // namespace kinstab::ui
