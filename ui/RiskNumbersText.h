// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The numbers beside the Study tab's risk charts (ui/RiskPanel.h) for one parameter set, as
// HTML: core's results (core/risk/SetRisk.h) formatted, rates to 3 significant digits.

#include "core/risk/SetRisk.h"

#include <QString>

namespace kinstab::ui {

QString riskNumbersHtml(const HazardCurve& c, const RiskSettings& s, const SetRisk& set);
// A set's name in the set selector: "set 1: μ = 0.4, t* = 0.099 s, ground".
QString riskSetName(const SetRisk& set);

} // namespace kinstab::ui
