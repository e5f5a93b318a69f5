// SPDX-License-Identifier: GPL-3.0-or-later
// The report's section on the project's free-standing blocks (issue 32): per block its geometry,
// alpha, p and the model; the overturning search on its level under the ground record and the
// block checks of the assessment; and its overturning map under a one-sine pulse (Zhang & Makris
// 2001, figs. 7-9), where the safe cape shows.

#include "core/rocking/OverturningMap.h"
#include "report/ComparisonTable.h"
#include "report/PlotFrame.h"
#include "report/ReportSections.h"

#include <algorithm>
#include <cmath>

namespace kinstab::report {

namespace {

const QColor kOverturns(160, 20, 40), kLeaves(235, 140, 30), kStands(0, 90, 181);

// The map's grid: wide enough for the safe cape of a slender block (Zhang & Makris 2001 fig. 8
// spans a_p/(alpha g) to 10 and omega_p/p to 10), coarse enough to cost seconds.
OverturningMapSpec reportMapSpec() {
    OverturningMapSpec s;
    s.shape = PulseShape::OneSine;
    s.amplitudeMin = 0.5;
    s.amplitudeMax = 10.0;
    s.frequencyMin = 0.5;
    s.frequencyMax = 10.0;
    s.amplitudePoints = 48;
    s.frequencyPoints = 48;
    return s;
}

// A surviving cell shaded by its largest |theta|/alpha (white: never lifted, blue: near 1).
QColor cellColour(const OverturningMap& m, std::size_t k) {
    if (m.overturns[k] == 1) return kOverturns;
    if (m.overturns[k] == 2) return kLeaves;
    const double t = std::clamp(static_cast<double>(m.maxThetaOverAlpha[k]), 0.0, 1.0);
    return QColor::fromRgbF(1.0 - 0.75 * t, 1.0 - 0.55 * t, 1.0 - 0.2 * t);
}

// The legend goes in a strip under the axes, as the γc contour map's: inside the plot it
// covered the cells of the upper right, where the safe cape of a slender block lies.
void paintMap(QPainter& pa, const QRectF& r, const OverturningMap& m) {
    const OverturningMapSpec& s = m.spec;
    const double dx = (s.frequencyMax - s.frequencyMin) / (s.frequencyPoints - 1);
    const double dy = (s.amplitudeMax - s.amplitudeMin) / (s.amplitudePoints - 1);
    const std::vector<LegendEntry> legend{
        {QStringLiteral("overturns"), kOverturns},
        {QStringLiteral("leaves the base (counted as overturning)"), kLeaves},
        {QStringLiteral("stands (shade: largest |θ|/α)"), kStands}};
    const FigureScale scale{r.width()};
    const double strip = legendRowsHeight(scale, legend.size(), 2);
    const QRectF plotArea = r.adjusted(0, 0, 0, -strip);
    PlotFrame f(plotArea, s.frequencyMin - dx / 2, s.frequencyMax + dx / 2, s.amplitudeMin - dy / 2,
                s.amplitudeMax + dy / 2);
    pa.setPen(Qt::NoPen);
    for (int i = 0; i < s.frequencyPoints; ++i)
        for (int j = 0; j < s.amplitudePoints; ++j) {
            const double x = m.frequencies[static_cast<std::size_t>(i)];
            const double y = m.amplitudes[static_cast<std::size_t>(j)];
            const QRectF cell(f.map(x - dx / 2, y + dy / 2), f.map(x + dx / 2, y - dy / 2));
            pa.fillRect(cell.adjusted(0, 0, 0.5, 0.5), cellColour(m, m.at(i, j)));
        }
    f.drawAxes(pa, QStringLiteral("ω_p / p"), QStringLiteral("a_p / (α g)"));
    drawLegendRows(pa, f.scale(),
                   QRectF(f.plot().left(), plotArea.bottom(), f.plot().width(), strip), legend, 2);
}

QString intervalsText(const BlockCheckPart& b) {
    if (b.intervals.empty()) return QStringLiteral("none up to %1 g").arg(num(b.searchLimit, 3));
    QStringList parts;
    for (const auto& [from, to] : b.intervals)
        parts << QStringLiteral("%1–%2").arg(num(from, 3), num(to, 3));
    return parts.join(QStringLiteral(", "));
}

void blockTable(ReportDocument& doc, const std::vector<BlockCheckPart>& blocks) {
    Table t{{"block", "level", "b (m)", "h (m)", "α (rad)", "b/h (g)", "p (rad/s)", "η", "μ",
             "floor peak (g)", "critical floor peak (g)", "critical PGA (g)"},
            // μ "none": the base holds the block, it never slides
            {},
            {1.1, 0.6, 0.6, 0.6, 0.7, 0.6, 0.8, 0.6, 0.6, 0.9, 1.0, 0.9},
            {Align::Left, Align::Right, Align::Right, Align::Right, Align::Right, Align::Right,
             Align::Right, Align::Right, Align::Right, Align::Right, Align::Right, Align::Right},
            {}};
    for (const BlockCheckPart& b : blocks) {
        const kinstab::Block& k = b.block.block;
        const double alpha = blockAlpha(k);
        t.rows.push_back({qs(b.block.name), QString::number(b.level), num(k.halfWidth, 3),
                          num(k.halfHeight, 3), num(alpha, 4), num(k.halfWidth / k.halfHeight, 3),
                          num(blockFrequency(k), 3),
                          num(b.block.restitution.value_or(housnerRestitution(alpha)), 3),
                          b.block.mu ? num(*b.block.mu, 2) : QStringLiteral("none"),
                          num(b.floorPeak, 3), num(b.criticalFloorPeak, 3, QStringLiteral("none")),
                          num(b.criticalPga, 3, QStringLiteral("none"))});
    }
    doc.addTable(t);
}

void blockDetail(ReportDocument& doc, const BlockCheckPart& b, const OverturningMap* map) {
    doc.addHeading(QStringLiteral("Block '%1'").arg(qs(b.block.name)), 2);
    doc.addParagraph(QStringLiteral("%1, on level %2. Overturning peaks of the level's motion "
                                    "(g): %3 (%4 runs). West's rule: it does not lift below a "
                                    "floor acceleration of b/h = %5 g.")
                         .arg(qs(blockModelText(b.block)))
                         .arg(b.level)
                         .arg(intervalsText(b))
                         .arg(b.runs)
                         .arg(num(b.block.block.halfWidth / b.block.block.halfHeight, 3)));
    if (!map || !map->complete) return;
    const OverturningMap m = *map;
    doc.addFigure({[m](QPainter& pa, const QRectF& r) { paintMap(pa, r, m); }, 0.62,
                   QStringLiteral("Overturning map of block '%1' under a one-sine pulse "
                                  "a_p sin(ω_p t) (Zhang & Makris 2001): exact equations, its "
                                  "restitution and friction, %2 × %3 runs. A stronger pulse "
                                  "above an overturning one may leave the block standing (the "
                                  "safe cape).")
                       .arg(qs(b.block.name))
                       .arg(m.spec.frequencyPoints)
                       .arg(m.spec.amplitudePoints)});
}

} // namespace

std::vector<OverturningMap> computeReportBlockMaps(const Project& p, SweepControl* control) {
    std::vector<OverturningMap> out;
    for (const FreeBlock& b : p.blocks) {
        if (control && control->isCancelled()) break;
        out.push_back(overturningMap(freeBlockModel(b), reportMapSpec(), control));
    }
    return out;
}

QStringList blockCitations(const ReportAnalysis& a) {
    if (!a.blocks || a.blocks->empty()) return {};
    return {QStringLiteral("G. W. Housner, \"The behavior of inverted pendulum structures during "
                           "earthquakes\", Bulletin of the Seismological Society of America "
                           "53(2), 1963, 403–417."),
            QStringLiteral("J. Zhang and N. Makris, \"Rocking response of free-standing blocks "
                           "under cycloidal pulses\", Journal of Engineering Mechanics 127(5), "
                           "2001, 473–483.")};
}

void addBlocksSection(ReportDocument& doc, const Project& p, const ReportAnalysis& r) {
    if (!r.blocks || r.blocks->empty()) return;
    doc.addSection(QStringLiteral("Free-standing blocks: rocking and overturning"));
    doc.addParagraph(
        QStringLiteral(
            "Each block is a rigid rectangular block (half-width b, half-height h, α = atan(b/h), "
            "p = √(3g/(4R)), R = √(b² + h²); Housner 1963) standing free on its level of the "
            "building's shear model (the floor settings of the floor-motion section). The ground "
            "record drives the building; the level's motion, scaled to a peak, drives the block "
            "with the exact equations of rocking, impacts at θ = 0 with the restitution η, and, "
            "where μ is given, sliding and slide-rocking (Zhang & Makris 2001), from rest until "
            "its "
            "fate is decided. The search scans peaks every %1 g up to %2 g and bisects every "
            "change (rocking near its threshold is chaotic: thin overturning intervals lie between "
            "standing peaks, which a coarser scan steps over); the "
            "smallest overturning peak is the critical floor peak, and the building being linear, "
            "times |PGA| / |floor peak| the critical ground PGA, compared with the ground "
            "acceleration of each code level as the slab's floor checks are.")
            .arg(200)
            .arg(num(p.critical.to, 2)));
    blockTable(doc, *r.blocks);
    if (hasBasis(r.assessment, CheckBasis::Block)) {
        doc.addHeading(QStringLiteral("Block checks"), 2);
        addComparisonTable(doc, r.assessment, CheckBasis::Block, {2.9, 2.0, 0.9, 1.0, 0.8, 2.0});
    }
    for (std::size_t k = 0; k < r.blocks->size(); ++k)
        blockDetail(doc, r.blocks->at(k), k < r.blockMaps.size() ? &r.blockMaps[k] : nullptr);
}

} // namespace kinstab::report
