// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RiskNumbersText.h"

#include <QObject>
#include <QStringList>

namespace kinstab::ui {

namespace {

// A rate to 3 significant digits, as the report writes it ("2.01e-04").
QString rate(double x) {
    return QString::number(x, 'e', 2);
}

QString g(double x) {
    return QString::number(x, 'g', 3) + " g";
}

QString row(const QString& name, const QString& value) {
    return QStringLiteral("<tr><td>%1</td><td align=\"right\">&nbsp;%2</td></tr>").arg(name, value);
}

QString closedForms(const RiskResult& r) {
    const QString first =
        r.firstOrder.why.empty()
            ? QObject::tr("%1 /yr").arg(rate(r.firstOrder.lambdaC))
            : QObject::tr("n/a: %1").arg(QString::fromStdString(r.firstOrder.why));
    const QString second =
        r.secondOrder.why.empty()
            ? QObject::tr("%1 /yr").arg(rate(r.secondOrder.lambdaC))
            : QObject::tr("n/a: %1").arg(QString::fromStdString(r.secondOrder.why));
    const QString k = r.firstOrder.why.empty()
                          ? QObject::tr(" (k = %1)").arg(QString::number(r.firstOrder.k, 'f', 2))
                          : QString();
    return row(QObject::tr("Cornell first order%1").arg(k), first) +
           row(QObject::tr("second order (%1 points)").arg(r.secondOrder.points), second);
}

QString targets(const RiskSettings& s, const SetRisk& set) {
    const RiskResult& r = *set.risk;
    QString out = row(QObject::tr("target rate"), QObject::tr("%1 /yr").arg(rate(s.targetRate)));
    out += row(QObject::tr("margin, target / λ_C"),
               set.margin
                   ? QString::number(*set.margin, 'f', 2) +
                         (*set.margin >= 1.0 ? QObject::tr(" (meets)") : QObject::tr(" (fails)"))
                   : QObject::tr("— (λ_C is 0)"));
    out += row(QObject::tr("median for the target"),
               r.targeted.medianG ? g(*r.targeted.medianG) : QObject::tr("none"));
    out += row(QObject::tr("x at P(C) = 10 %"), g(r.imAtTenPercent));
    if (r.pAtIm && s.imG)
        out += row(QObject::tr("P(C) at %1 (target 10 %)").arg(g(*s.imG)),
                   QString::number(*r.pAtIm, 'f', 3));
    return out;
}

QString bootstrap(const SetRisk& set) {
    if (!set.bootstrap) return {};
    const RiskBootstrap& b = *set.bootstrap;
    return row(
        QObject::tr("λ_C 5 / 50 / 95 % (%1 of %2 resamples fitted)").arg(b.fitted).arg(b.resamples),
        QStringLiteral("%1 / %2 / %3")
            .arg(rate(b.lambdaC.p5), rate(b.lambdaC.p50), rate(b.lambdaC.p95)));
}

} // namespace

QString riskSetName(const SetRisk& set) {
    const StudyRow& p = set.fragility.parameters;
    return QObject::tr("set %1: μ = %2, t* = %3 s, %4")
        .arg(p.set + 1)
        .arg(p.mu)
        .arg(p.tstar)
        .arg(QString::fromStdString(studyDriverText(p)));
}

QString riskNumbersHtml(const HazardCurve& c, const RiskSettings& s, const SetRisk& set) {
    const Fragility& f = set.fragility;
    QString html = QObject::tr("<b>%1</b><br>%2 records, %3 collapse")
                       .arg(riskSetName(set).toHtmlEscaped())
                       .arg(f.records)
                       .arg(f.collapsed);
    if (!set.risk)
        return html + QObject::tr("<br>No fitted fragility: %1.")
                          .arg(QString::fromStdString(f.noFit).toHtmlEscaped());
    const RiskResult& r = *set.risk;
    html += QStringLiteral("<table cellspacing=\"2\">");
    html +=
        row(QObject::tr("fragility θ, β"),
            QStringLiteral("%1, %2").arg(g(r.fragility.medianG)).arg(r.fragility.beta, 0, 'f', 3));
    html += row(QObject::tr("<b>λ_C, annual rate of collapse</b>"),
                QObject::tr("<b>%1 /yr</b>").arg(rate(r.integral.lambdaC)));
    html += row(QObject::tr("&nbsp;&nbsp;within the curve"),
                QObject::tr("%1 /yr").arg(rate(r.integral.withinCurve)));
    html += row(QObject::tr("&nbsp;&nbsp;beyond %1").arg(g(c.points.back().imG)),
                QObject::tr("%1 /yr").arg(rate(r.integral.beyondLastPoint)));
    html += row(QObject::tr("<b>P(collapse in %1 years)</b>").arg(s.years),
                QStringLiteral("<b>%1</b>").arg(QString::number(r.pInYears, 'g', 3)));
    html += targets(s, set) + closedForms(r) + bootstrap(set);
    html += QStringLiteral("</table>");
    html += QObject::tr("<small>λ(x) linear in log-log between the curve's points, each segment "
                        "integrated in closed form; the rate beyond the last point counted with "
                        "P(C | x_max); none below the first.</small>");
    return html;
}

} // namespace kinstab::ui
