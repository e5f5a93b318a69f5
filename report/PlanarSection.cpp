// SPDX-License-Identifier: GPL-3.0-or-later
// The planar model's inputs in the report (docs/user-guide.md, Furgerson 1980 ch. VI): shown only
// when the project's model is planar; the surfaces, A_crit(f) and the check then come from it.
#include "core/records/ShippedRecords.h"
#include "report/QuantityTable.h"
#include "report/ReportSections.h"

namespace kinstab::report {

namespace {
// One line below the table: the shipped record's note, or what else moves the slab vertically.
QString verticalDescription(const PlanarSettings& s) {
    switch (s.vertical) {
    case VerticalSource::None:
        return QStringLiteral("Vertical motion: none (gravity only).");
    case VerticalSource::Rsn68Up:
        return QString::fromUtf8(kRsn68UpNote);
    case VerticalSource::File:
        return QStringLiteral("Vertical motion: record file %1.").arg(qs(s.verticalPath));
    }
    return {};
}
} // namespace

QString modelName(const Project& p) {
    if (p.model != ModelKind::Planar)
        return QStringLiteral("1-DOF friction-held slab on walls (Furgerson 1980, ch. IV–V)");
    return p.planar.vertical == VerticalSource::None
               ? QStringLiteral("planar 2-DOF slab, no vertical motion (Furgerson 1980, ch. VI)")
               : QStringLiteral("planar 2-DOF slab with vertical motion (Furgerson 1980, ch. VI)");
}

void addPlanarInputs(ReportDocument& doc, const Project& p) {
    if (p.model != ModelKind::Planar) return;
    const PlanarSettings& s = p.planar;
    doc.addHeading(QStringLiteral("Planar model"), 2);
    doc.addParagraph(QStringLiteral(
        "The slab slides in both horizontal directions: friction acts along the relative "
        "velocity with the normal force (1 + a_z) of the vertical motion; it falls when its slip "
        "across the walls exceeds the bearing limit or its slip along them exceeds Θ. The across-"
        "wall motion a_x is the enveloped sine of the sweep (amplitude A = A_x, frequency f = "
        "f_x); the along-wall motion a_y has the same envelope. Every surface, A_crit(f) and the "
        "design check in this report come from the planar model."));
    Table t = quantityTable();
    t.rows.push_back({"frequency along the walls", "f_y", num(s.fyHz, 3), "Hz"});
    t.rows.push_back({"amplitude ratio along / across", "A_y/A_x", num(s.ayRatio, 3), ""});
    t.rows.push_back({"along-wall limit (2 length / width)", "Θ", num(s.theta, 2), ""});
    t.rows.push_back({"normalization of S_max", "", qs(normalizationName(s.normalization)), ""});
    t.rows.push_back({"vertical motion", "a_z",
                      s.vertical == VerticalSource::None      ? QStringLiteral("none")
                      : s.vertical == VerticalSource::Rsn68Up ? QStringLiteral("RSN68 UP")
                                                              : qs(s.verticalPath),
                      ""});
    doc.addTable(t);
    doc.addParagraph(verticalDescription(s), true);
}

} // namespace kinstab::report
