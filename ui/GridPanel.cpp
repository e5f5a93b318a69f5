// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/GridPanel.h"

#include "core/base/InputLimits.h"
#include "core/excitation/FrequencyRange.h"
#include "ui/NumberField.h"

#include <QFormLayout>
#include <QLabel>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

GridPanel::GridPanel(QWidget* parent) : InputPanel(parent), m_count(new QLabel(this)) {
    const QString aTip =
        tr("Peak floor acceleration A of the enveloped sine, in g. The slab "
           "cannot slip below A = μ; the paper's critical region is near 0.7–1.15.");
    const QString fTip = tr("Frequency f of the floor motion, in Hz: the building's fundamental "
                            "frequency 1/T. The paper covers 0.5–1.125 Hz.");
    m_aFrom = addField("aFrom", tr("A &from:"), tr("g"), aTip);
    m_aTo = addField("aTo", tr("A to:"), tr("g"), aTip);
    m_aStep = addField("aStep", tr("A step:"), tr("g"), tr("Spacing of the amplitude grid."));
    m_fFrom = addField("fFrom", tr("f fro&m:"), tr("Hz"), fTip);
    m_fTo = addField("fTo", tr("f to:"), tr("Hz"), fTip);
    m_fStep = addField("fStep", tr("f step:"), tr("Hz"), tr("Spacing of the frequency grid."));
    form()->addRow(m_count);
    m_aFrom->setCheck(rangeCheck(0, limits::kMaxAmplitudeG));
    m_aTo->setCheck([this](double v) {
        const auto from = m_aFrom->value();
        if (v > limits::kMaxAmplitudeG)
            return tr("must be ≤ %1 g (got %2)").arg(limits::kMaxAmplitudeG).arg(v);
        return from && v < *from ? tr("must be ≥ A from (%1)").arg(*from) : QString();
    });
    m_aStep->setCheck([this](double v) {
        return rangeProblem(m_aFrom->value().value_or(0), m_aTo->value().value_or(0), v, tr("A"));
    });
    m_fFrom->setCheck(rangeCheck(kMinFrequencyHz, kMaxFrequencyHz));
    m_fTo->setCheck([this](double v) {
        const auto from = m_fFrom->value();
        if (v > kMaxFrequencyHz) return tr("must be ≤ %1 Hz (got %2)").arg(kMaxFrequencyHz).arg(v);
        return from && v < *from ? tr("must be ≥ f from (%1)").arg(*from) : QString();
    });
    m_fStep->setCheck([this](double v) {
        return rangeProblem(m_fFrom->value().value_or(0), m_fTo->value().value_or(0), v, tr("f"));
    });
    for (NumberField* f : {m_aFrom, m_aTo, m_aStep, m_fFrom, m_fTo, m_fStep})
        connect(f, &NumberField::edited, this, [this] {
            for (NumberField* g : {m_aTo, m_aStep, m_fTo, m_fStep})
                g->revalidate();
            updateCount();
        });
    setRanges(GridRanges{});
}

QString GridPanel::rangeProblem(double from, double to, double step, const QString& what) const {
    if (!(step > 0)) return tr("must be > 0 (got %1)").arg(step);
    const double n = (to - from) / step + 1;
    if (n > 500) return tr("gives %1 %2 values; at most 500").arg(static_cast<long>(n)).arg(what);
    return {};
}

void GridPanel::updateCount() {
    if (!isValid()) {
        m_count->clear();
        return;
    }
    const SweepGrid g = grid();
    m_count->setText(
        tr("%1 × %2 = %3 points").arg(g.amplitudes.size()).arg(g.frequencies.size()).arg(g.size()));
}

GridRanges GridPanel::ranges() const {
    GridRanges r;
    r.aFrom = m_aFrom->value().value_or(r.aFrom);
    r.aTo = m_aTo->value().value_or(r.aTo);
    r.aStep = m_aStep->value().value_or(r.aStep);
    r.fFrom = m_fFrom->value().value_or(r.fFrom);
    r.fTo = m_fTo->value().value_or(r.fTo);
    r.fStep = m_fStep->value().value_or(r.fStep);
    return r;
}

void GridPanel::setRanges(const GridRanges& r) {
    m_aFrom->setValue(r.aFrom);
    m_aTo->setValue(r.aTo);
    m_aStep->setValue(r.aStep);
    m_fFrom->setValue(r.fFrom);
    m_fTo->setValue(r.fTo);
    m_fStep->setValue(r.fStep);
}

bool GridPanel::setGrid(const SweepGrid& g) {
    if (g.amplitudes.empty() || g.frequencies.empty()) return true;
    GridRanges r = ranges();
    bool even = true;
    auto fit = [&even](const std::vector<double>& v, double& from, double& to, double& step) {
        from = v.front();
        to = v.back();
        if (v.size() > 1) step = (to - from) / static_cast<double>(v.size() - 1);
        for (std::size_t i = 0; i < v.size(); ++i)
            if (std::abs(v[i] - (from + static_cast<double>(i) * step)) >
                1e-9 * std::max(1.0, std::abs(to)))
                even = false;
    };
    fit(g.amplitudes, r.aFrom, r.aTo, r.aStep);
    fit(g.frequencies, r.fFrom, r.fTo, r.fStep);
    setRanges(r);
    return even;
}

SweepGrid GridPanel::grid() const {
    const GridRanges r = ranges();
    return {linspaceStep(r.aFrom, r.aTo, r.aStep), linspaceStep(r.fFrom, r.fTo, r.fStep)};
}

} // namespace kinstab::ui
