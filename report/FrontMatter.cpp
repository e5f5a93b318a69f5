// SPDX-License-Identifier: GPL-3.0-or-later
// Page 1 above the verdict: who issues the report and for whom (the project's "info"), the
// revision table and the signature/seal block; and, beside the verdict, the acceptance
// criterion and the disclaimer.
#include "report/ReportSections.h"

#include <QPainter>

namespace kinstab::ui::report {

namespace {

QString orBlank(const std::string& s) {
    return s.empty() ? QStringLiteral("—") : qs(s);
}

void addRevisionTable(ReportDocument& doc, const ProjectInfo& info) {
    if (info.revisions.empty()) return;
    doc.addHeading(QStringLiteral("Revisions"), 2);
    Table t{{"rev.", "date", "description"}, {}, {0.8, 1.4, 6}, {}, {}};
    for (const Revision& r : info.revisions)
        t.rows.push_back({qs(r.id), qs(r.date), qs(r.description)});
    t.boldRows.push_back(static_cast<int>(t.rows.size()) - 1); // the current issue
    doc.addTable(t);
}

// One box: a role, the name, then lines to sign and date; the engineer's box leaves room for
// the seal or stamp.
void paintSignatureBox(QPainter& p, const QRectF& r, const QString& role, const QString& name,
                       bool seal) {
    const double u = r.height() / 20.0; // layout unit: the block is 20 units high
    p.setPen(QPen(Qt::black, u * 0.08));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    QFont f = p.font();
    f.setPixelSize(static_cast<int>(u * 1.3));
    f.setBold(true);
    p.setFont(f);
    const QRectF text = r.adjusted(u, u * 0.6, -u, 0);
    p.drawText(QRectF(text.left(), text.top(), text.width(), u * 2), Qt::AlignLeft, role);
    f.setBold(false);
    p.setFont(f);
    p.drawText(QRectF(text.left(), text.top() + u * 2, text.width(), u * 4),
               Qt::AlignLeft | Qt::TextWordWrap, name);
    const double lineLeft = text.left(), lineRight = text.right();
    for (const auto& [label, y] : {std::pair{QStringLiteral("signature"), r.bottom() - u * 5.5},
                                   std::pair{QStringLiteral("date"), r.bottom() - u * 1.8}}) {
        p.drawLine(QPointF(lineLeft, y), QPointF(lineRight, y));
        p.drawText(QRectF(lineLeft, y + u * 0.2, text.width(), u * 1.6), Qt::AlignLeft, label);
    }
    if (!seal) return;
    p.setPen(QPen(Qt::gray, u * 0.08, Qt::DashLine));
    const double d = u * 7.5;
    p.drawEllipse(QRectF(r.center().x() - d / 2, r.top() + u * 6.2, d, d));
    p.drawText(QRectF(r.center().x() - d / 2, r.top() + u * 6.2, d, d), Qt::AlignCenter,
               QStringLiteral("seal"));
}

} // namespace

void addRevisions(ReportDocument& doc, const Project& p) {
    addRevisionTable(doc, p.info);
}

void addSignatureBlock(ReportDocument& doc, const Project& p) {
    const ProjectInfo& in = p.info;
    const QString engineer =
        orBlank(in.engineer) +
        (in.registration.empty() ? QString() : QStringLiteral("\nReg. no. ") + qs(in.registration));
    const QString prepared = orBlank(in.preparedBy), checked = orBlank(in.checkedBy);
    doc.addDrawing({[prepared, checked, engineer](QPainter& pa, const QRectF& r) {
                        const double gap = r.width() * 0.02;
                        const double w = (r.width() - 2 * gap) / 3;
                        const QRectF box(r.left(), r.top(), w, r.height());
                        paintSignatureBox(pa, box, QStringLiteral("Prepared by"), prepared, false);
                        paintSignatureBox(pa, box.translated(w + gap, 0),
                                          QStringLiteral("Checked by"), checked, false);
                        paintSignatureBox(pa, box.translated(2 * (w + gap), 0),
                                          QStringLiteral("Engineer of record"), engineer, true);
                    },
                    0.26, QString()});
}

void addAcceptanceCriterion(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    if (a.check.codes.empty()) return;
    const QString crit = recordGoverns(p, a) ? QStringLiteral("the record's critical peak")
                                             : QStringLiteral("A_crit");
    doc.addParagraph(
        QStringLiteral(
            "Acceptance criterion: margin = %1 / (F_top/w_top), the floor acceleration that "
            "slides the slab off its walls divided by the top-floor acceleration the code "
            "requires the structure to resist. A margin greater than 1 is acceptable: the "
            "structure reaches its code strength before the slab can slide off (member "
            "overstress governs). A margin below 1 is not: the slab slides off at a floor "
            "acceleration the code requires the structure to withstand (kinetic instability "
            "governs), and the slab seating must be lengthened or the slab restrained. The "
            "verdict does not cover the strength of the members, the walls or the slab "
            "themselves, floors other than the top floor, nor the limitations listed under "
            "\"Assumptions and limitations\".")
            .arg(crit));
    doc.addParagraph(
        QStringLiteral("This report was produced by software (kinstab %1). Its inputs and results "
                       "must be checked by a qualified engineer, who is responsible for the "
                       "design and signs below or on the title block.")
            .arg(QStringLiteral(KINSTAB_VERSION)),
        true);
}

} // namespace kinstab::ui::report
