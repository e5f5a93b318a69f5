// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/FigurePresets.h"

namespace kinstab::ui {

namespace {

TeachingParams paperParams(EnvelopePreset e, TauScale s, double a, double f) {
    TeachingParams p;
    p.envelope = e;
    p.scale = s;
    p.amplitude = a;
    p.frequencyHz = f;
    p.mu = 0.6;                               // the model default (docs/theory.md §8)
    p.wallWidthM = wallWidthFromTstar(0.099); // the "8 inch" wall, t* = 0.099 s (Table 4)
    p.limit = 1.0;                            // bearing = d/2 (ch. IV)
    return p;
}

FigurePreset surface(int fig, EnvelopePreset e, TauScale s) {
    const QString env = e == EnvelopePreset::Fast       ? QStringLiteral("fast")
                        : e == EnvelopePreset::Moderate ? QStringLiteral("moderately")
                                                        : QStringLiteral("slowly");
    const QString ref = s == TauScale::TauMax ? QStringLiteral("τ_max") : QStringLiteral("τ_rise");
    const QString shaking = e == EnvelopePreset::Fast       ? QStringLiteral("Sudden")
                            : e == EnvelopePreset::Moderate ? QStringLiteral("Moderate")
                                                            : QStringLiteral("Slowly building");
    FigurePreset p;
    p.id = QStringLiteral("fig%1").arg(fig);
    // The outcome named here is checked against the run (tests/ui/tst_teaching_presentation).
    p.title = QStringLiteral("%1 shaking at 1 Hz: the slab walks off").arg(shaking);
    p.figure = QStringLiteral("Fig. %1, γc = %2/τc").arg(fig).arg(ref);
    p.caption =
        QStringLiteral("Surface γc(A, f) for the scaling parameter %1, computed with the base "
                       "acceleration contained in a %2 rising envelope.")
            .arg(ref, env);
    // The run shown: A = 1.0 g at the example building's 1 Hz (ch. V), on the surface.
    p.params = paperParams(e, s, 1.0, 1.0);
    p.range = kPaperRange;
    return p;
}

FigurePreset planar(int fig, double fyHz) {
    FigurePreset p;
    p.id = QStringLiteral("fig%1").arg(fig);
    p.title =
        QStringLiteral("Shaking in two directions, %1 Hz along the walls").arg(fyHz, 0, 'g', 3);
    p.figure = QStringLiteral("Fig. %1, planar").arg(fig);
    p.caption =
        QStringLiteral("Surface γc(A_x, f_x), γc = τ_max/τc, planar model, moderately rising "
                       "envelope, A_y = 0.9 A_x, f_y = %1 Hz. Vertical: gravity only (the "
                       "paper added the 1971 Pacoima Dam vertical, not publicly available).")
            .arg(fyHz, 0, 'g', 3);
    p.params = paperParams(EnvelopePreset::Moderate, TauScale::TauMax, 1.0, 1.0);
    p.params.model = TeachingModel::Planar;
    p.params.fyHz = fyHz;
    p.params.ayRatio = 0.9; // ch. VI: the ratio of Pacoima Dam's horizontal peaks
    p.params.theta = 20.0;  // ch. VI
    p.range = kPlanarRange;
    return p;
}

std::vector<FigurePreset> build() {
    std::vector<FigurePreset> v;
    v.push_back(surface(28, EnvelopePreset::Fast, TauScale::TauMax));
    v.push_back(surface(29, EnvelopePreset::Moderate, TauScale::TauMax));
    v.push_back(surface(30, EnvelopePreset::Slow, TauScale::TauMax));
    v.push_back(surface(31, EnvelopePreset::Fast, TauScale::TauRise));
    v.push_back(surface(32, EnvelopePreset::Moderate, TauScale::TauRise));
    v.push_back(surface(33, EnvelopePreset::Slow, TauScale::TauRise));
    v.push_back(
        {QStringLiteral("fig34"),
         QStringLiteral("Shaking at 0.75 Hz: how soon the slab falls as A grows"),
         QStringLiteral("Fig. 34, τc against A"),
         QStringLiteral("Nondimensional collapse time τc vs. amplitude A given fixed frequency "
                        "f = 0.75 Hz and moderately rising acceleration envelope."),
         paperParams(EnvelopePreset::Moderate, TauScale::TauMax, 1.0, 0.75), MapMode::Slice,
         kPaperRange});
    v.push_back(
        {QStringLiteral("fig35"), QStringLiteral("How far the slab slides, shaking at 1.125 Hz"),
         QStringLiteral("Fig. 35, δ(τ) with the envelope"),
         QStringLiteral("Nondimensional relative displacement δ(τ) vs. τ with the acceleration "
                        "envelope, A = 1.0, f = 1.125 Hz, moderately rising envelope."),
         paperParams(EnvelopePreset::Moderate, TauScale::TauMax, 1.0, 1.125), MapMode::Surface,
         kPaperRange});
    const double fy[] = {0.2, 0.5, 1.0, 2.0, 5.0, 10.0};
    for (int i = 0; i < 6; ++i)
        v.push_back(planar(37 + i, fy[i]));
    return v;
}

} // namespace

const std::vector<FigurePreset>& figurePresets() {
    static const std::vector<FigurePreset> presets = build();
    return presets;
}

QString presetListText(const FigurePreset& p) {
    return QStringLiteral("%1  ·  %2").arg(p.title, p.figure);
}

const FigurePreset* findFigurePreset(const QString& id) {
    for (const FigurePreset& p : figurePresets())
        if (p.id == id) return &p;
    return nullptr;
}

} // namespace kinstab::ui
