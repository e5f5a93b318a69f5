// SPDX-License-Identifier: GPL-3.0-or-later
// Page 1 above the verdict: who issues the report and for whom (the project's "info"), the
// revision table and the signature/seal block; and, beside the verdict, the acceptance
// criterion and the disclaimer.
#include "report/ReportSections.h"
#include "report/WrappedText.h"

#include <QPainter>

#include <algorithm>

namespace kinstab::report {

namespace {

QString orBlank(const std::string& s) {
    return s.empty() ? QStringLiteral("—") : qs(s);
}

// Revisions page 1 lists: the current issue and the two before it. Fifty revisions of 200
// characters each would push the verdict and the signature block off the signed page; the
// whole history then follows the report (addRevisionHistory).
constexpr std::size_t kRevisionsOnPage1 = 3;

void addRevisionTable(ReportDocument& doc, const std::vector<Revision>& revisions) {
    Table t{{"revision", "date", "description"}, {}, {1, 1.4, 6}, {}, {}};
    for (const Revision& r : revisions)
        t.rows.push_back({qs(r.id), qs(r.date), qs(r.description)});
    t.boldRows.push_back(static_cast<int>(t.rows.size()) - 1); // the current issue
    doc.addTable(t);
}

// One box of the signature block, 12 units high: the role, the name, then lines to sign and date;
// the engineer's box keeps room on the right for the seal or stamp.
void paintSignatureBox(QPainter& p, const QRectF& r, const QString& role, const QString& name,
                       bool seal) {
    const double u = r.height() / 12.0;
    p.setPen(QPen(Qt::black, u * 0.05));
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    QFont f = p.font();
    f.setPixelSize(std::max(1, static_cast<int>(u * 1.15)));
    f.setBold(true);
    p.setFont(f);
    const double left = r.left() + u * 0.6;
    const double width = r.width() - u * (seal ? 7.0 : 1.2);
    p.drawText(QRectF(left, r.top() + u * 0.4, width, u * 1.5), Qt::AlignLeft, role);
    f.setBold(false);
    p.setFont(f);
    // Two lines for the name (engineer: name, then the registration), cut with "…" beyond them:
    // the lines to sign and date below stay clear whatever the project says.
    const QStringList parts = name.split(QLatin1Char('\n'));
    const QString shown = parts.size() > 1
                              ? elidedToLines(parts[0], f, width, 1, p.device()) + "\n" +
                                    elidedToLines(parts[1], f, width, 1, p.device())
                              : elidedToLines(name, f, width, 2, p.device());
    paintWrapped(p, QRectF(left, r.top() + u * 1.9, width, u * 3.0), shown);
    for (const auto& [label, y] : {std::pair{QStringLiteral("signature"), r.top() + u * 8.0},
                                   std::pair{QStringLiteral("date"), r.top() + u * 10.3}}) {
        p.drawLine(QPointF(left, y), QPointF(left + width, y));
        p.drawText(QRectF(left, y + u * 0.1, width, u * 1.5), Qt::AlignLeft, label);
    }
    if (!seal) return;
    p.setPen(QPen(Qt::gray, u * 0.05, Qt::DashLine));
    const QRectF circle(r.right() - u * 6.2, r.top() + u * 2.0, u * 5.6, u * 5.6);
    p.drawEllipse(circle);
    p.drawText(circle, Qt::AlignCenter, QStringLiteral("seal"));
}

} // namespace

void addRevisions(ReportDocument& doc, const Project& p) {
    const std::vector<Revision>& all = p.info.revisions;
    if (all.empty()) return;
    const std::size_t earlier = all.size() - std::min(all.size(), kRevisionsOnPage1);
    addRevisionTable(doc, {all.begin() + static_cast<std::ptrdiff_t>(earlier), all.end()});
    if (earlier > 0)
        doc.addParagraph(QStringLiteral("%1 earlier revision%2 (from %3): see the revision history "
                                        "at the end of the report.")
                             .arg(earlier)
                             .arg(earlier == 1 ? "" : "s")
                             .arg(qs(all.front().id)),
                         true);
}

void addRevisionHistory(ReportDocument& doc, const Project& p) {
    if (p.info.revisions.size() <= kRevisionsOnPage1) return;
    doc.addSection(QStringLiteral("Revision history"));
    addRevisionTable(doc, p.info.revisions);
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
                    0.155, QString()});
}

void addAcceptanceCriterion(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    const Assessment& s = a.assessment;
    if (s.checks.empty()) return;
    (void)p;
    QStringList criteria;
    if (hasBasis(s, CheckBasis::Sine) || hasBasis(s, CheckBasis::Planar) ||
        hasBasis(s, CheckBasis::Record))
        criteria << QStringLiteral(
            "for the code-ratio checks (sine, planar, record), margin = critical floor peak / "
            "(F_top/w_top): above 1 the structure reaches its code strength before the slab can "
            "slide off (member overstress governs); below 1 the slab slides off at a floor "
            "acceleration the code requires the structure to withstand (kinetic instability "
            "governs)");
    if (hasBasis(s, CheckBasis::Floors))
        criteria << QStringLiteral(
            "for the floor checks, margin = the ground PGA at which the slab on its level falls / "
            "the ground acceleration of the code level (the code's own floor formula beside "
            "it governs where it fails while the ground comparison holds): above 1 the slab stays "
            "seated at that level of shaking, "
            "below 1 it slides off");
    if (hasBasis(s, CheckBasis::Block))
        criteria << QStringLiteral(
            "for the block checks, margin = the ground PGA at which the free-standing block on "
            "its level overturns / the ground acceleration of the code level (the code's floor "
            "formula beside it, as for the floor checks): above 1 the block stays standing at "
            "that level of shaking, below 1 it overturns and must be anchored or restrained");
    doc.addParagraph(
        QStringLiteral("Acceptance criterion: every check's margin must exceed 1; %1. A check "
                       "that does not hold asks for a longer slab seating or a restrained slab. "
                       "The assessment does not cover the strength of the members, the walls or "
                       "the slab themselves.")
            .arg(criteria.join(QStringLiteral("; "))));
    doc.addParagraph(
        QStringLiteral("This report was produced by software (kinstab %1). Its inputs and results "
                       "must be checked by a qualified engineer, who is responsible for the "
                       "design and signs it in the block on page 1.")
            .arg(QStringLiteral(KINSTAB_VERSION)),
        true);
}

} // namespace kinstab::report
