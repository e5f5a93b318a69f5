// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/PlanarVertical.h"

#include "core/codes/Building.h"
#include "core/records/RecordReader.h"

#include <QFile>
#include <QFileInfo>

namespace kinstab::ui {

QString defaultVerticalRecordPath() {
    return QStringLiteral(":/records/RSN68_SFERN_PEL-UP.AT2");
}

QString defaultVerticalRecordNote() {
    return QObject::tr(
        "Vertical motion: 1971 San Fernando, LA Hollywood Storage FF, UP (NGA RSN68) stands in for "
        "the paper's Pacoima Dam vertical, which is not publicly available.");
}

std::optional<Accelerogram> readVerticalRecord(const PlanarSettings& s) {
    if (s.vertical == VerticalSource::None) return std::nullopt;
    const QString path = s.vertical == VerticalSource::Rsn68Up
                             ? defaultVerticalRecordPath()
                             : QString::fromStdString(s.verticalPath);
    const std::string field = "planar.vertical = '" + path.toStdString() + "': ";
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) throw InputError(field + f.errorString().toStdString());
    try {
        return parseRecord(RecordText(f.readAll().toStdString(), path.toStdString()));
    } catch (const RecordError& e) {
        throw InputError(field + e.what());
    }
}

PlanarCase projectPlanarCase(const Slab1DCase& common, const PlanarSettings& s) {
    const std::optional<Accelerogram> record = readVerticalRecord(s);
    return planarCaseFrom(common, s, record ? verticalMotion(*record, common.tstar) : nullptr);
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
