// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Study tab's risk charts (docs/studies.md, "Risk"), each against the intensity on a log axis
// over the same decades, so the three line up: the site's hazard curve (annual rate of exceedance,
// log-log) with the target rate; the selected set's fitted fragility P(C | x) with its records'
// empirical points; and the integrand of lambda_C per unit of ln x with the rate beyond the
// curve's last point stated, so the user sees which intensities drive the risk. Every number comes
// from core (core/risk/SetRisk.h): the charts only draw.

#include "core/risk/SetRisk.h"

#include <QString>

class QChart;

namespace kinstab::ui {

// The decades the charts share: from the power of ten at or below the curve's first intensity to
// the one at or above its last.
struct RiskAxisRange {
    double lo = 0.01, hi = 10; // g
};
RiskAxisRange riskAxisRange(const HazardCurve& c);

void fillHazardChart(QChart* chart, const HazardCurve& c, double targetRate);
// set: none clears the chart (a set without a fit).
void fillRiskFragilityChart(QChart* chart, const HazardCurve& c, const SetRisk* set);
void fillIntegrandChart(QChart* chart, const HazardCurve& c, const SetRisk* set);
void clearRiskChart(QChart* chart, const QString& title);

} // namespace kinstab::ui
