// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/BlockPresets.h"

#include "core/base/PhysicalConstants.h"
#include "core/rocking/FreeRocking.h"

#include <QCoreApplication>

#include <cmath>
#include <numbers>

namespace kinstab::ui {

namespace {

QString tr(const char* s) {
    return QCoreApplication::translate("BlockPresets", s);
}

BlockPreset housnerFree() {
    BlockCase c;
    c.model.block = {0.2, 1.0};
    c.model.initialTilt = 0.5;
    const double p = blockFrequency(c.model.block);
    return {QStringLiteral("housner-free"), tr("Free rocking from a tilt, impacts lose energy"),
            QStringLiteral("Housner 1963"),
            tr("Released from rest at θ0 = α/2: the linearised first impact comes at "
               "(1/p) acosh(1/(1 − θ0/α)) = %1 s; each impact keeps η = 1 − 1.5 sin²α = %2 of "
               "the angular velocity, and the block rocks about one corner, then the other.")
                .arg(housnerQuarterPeriod(p, 0.5), 0, 'f', 3)
                .arg(housnerRestitution(blockAlpha(c.model.block)), 0, 'f', 3),
            c};
}

BlockPreset makrisRoussos() {
    BlockCase c;
    c.model.block = {0.2, 0.6};
    c.model.equations = RockingEquations::Linearised;
    Pulse pulse;
    pulse.shape = PulseShape::HalfSine;
    pulse.frequencyHz = 1.0;
    pulse.amplitude = -5.44 / kStandardGravity;
    c.pulse = pulse;
    return {QStringLiteral("makris-roussos"), tr("A half-sine pulse overturns the block"),
            QStringLiteral("Makris & Roussos 2000"),
            tr("Their worked example: b = 0.2 m, h = 0.6 m, a half-sine of 1 Hz. Eq. 27 gives "
               "5.439 m/s² as the least amplitude that overturns it; 5.44 m/s² does, without an "
               "impact (5.43 m/s² only rocks)."),
            c};
}

BlockCase zhangMakrisCase(double amplitudeOverAlphaG) {
    BlockCase c;
    c.model.block = blockFromAlphaP(0.25, 2.14);
    c.model.restitution = 0.9;
    c.model.equations = RockingEquations::Linearised;
    Pulse pulse;
    pulse.shape = PulseShape::OneSine;
    pulse.frequencyHz = 5.0 * 2.14 / (2.0 * std::numbers::pi); // omega_p / p = 5
    pulse.amplitude = -amplitudeOverAlphaG * 0.25;
    c.pulse = pulse;
    return c;
}

BlockPreset zhangMakrisOver() {
    return {QStringLiteral("zhang-makris-overturns"),
            tr("One-sine pulse: overturns after one impact"), QStringLiteral("Zhang & Makris 2001"),
            tr("p = 2.14 rad/s, α = 0.25, η = 0.9, ω_p/p = 5, a_p = 4.5 αg: the block rocks, "
               "hits its base once, then overturns."),
            zhangMakrisCase(4.5)};
}

BlockPreset zhangMakrisCape() {
    return {QStringLiteral("zhang-makris-cape"),
            tr("Safe cape: a stronger pulse that does not overturn"),
            QStringLiteral("Zhang & Makris 2001"),
            tr("The same block and pulse at 7.0 αg, stronger than 4.5 αg, survives: the second "
               "half of the pulse brings it back before it passes its corner. Overturning "
               "resumes above 7.168 αg (eq. 47). See the one-sine map of the Model panel."),
            zhangMakrisCase(7.0)};
}

BlockPreset rectangular() {
    BlockCase c;
    c.model.block = {0.2, 1.0};
    c.model.equations = RockingEquations::Linearised;
    const double p = blockFrequency(c.model.block), alpha = blockAlpha(c.model.block);
    const double psi = 2.0;
    const double t1 = std::acosh(1.0 + 1.0 / (2.0 * psi * (psi - 1.0))) / p;
    Pulse pulse;
    pulse.shape = PulseShape::Rectangular;
    pulse.amplitude = -psi * alpha;
    pulse.durationS = 1.02 * t1;
    c.pulse = pulse;
    return {QStringLiteral("housner-rectangular"),
            tr("Rectangular pulse just long enough to overturn"), QStringLiteral("Housner 1963"),
            tr("2αg for t1 = %1 s, 2 % longer than Housner's eq. 9, cosh(p t1) = 1 + 1/(2ψ(ψ − 1)) "
               "with ψ = 2: after the pulse the block drifts on past its corner and falls.")
                .arg(pulse.durationS, 0, 'f', 3),
            c};
}

BlockPreset sliding() {
    BlockCase c;
    c.model.block = {0.5, 0.5};
    c.model.mu = 0.3;
    Pulse pulse;
    pulse.shape = PulseShape::HalfSine;
    pulse.frequencyHz = 2.0;
    pulse.amplitude = 0.6;
    c.pulse = pulse;
    return {QStringLiteral("squat-slides"), tr("A squat block on a slippery base slides"),
            QStringLiteral("Shenton 1996"),
            tr("b = h = 0.5 m (tan α = 1), μ = 0.3: friction gives way at 0.3 g, long before "
               "the block could tip, so it slides on its base and never rocks."),
            c};
}

} // namespace

const std::vector<BlockPreset>& blockPresets() {
    static const std::vector<BlockPreset> all{housnerFree(),     makrisRoussos(), zhangMakrisOver(),
                                              zhangMakrisCape(), rectangular(),   sliding()};
    return all;
}

const BlockPreset* findBlockPreset(const QString& id) {
    for (const BlockPreset& p : blockPresets())
        if (p.id == id) return &p;
    return nullptr;
}

} // namespace kinstab::ui
