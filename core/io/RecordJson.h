// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A record's JSON as kinstab-cli writes it (docs/user-guide.md "The command line"): the
// accelerogram's header and peak, the floor filter it went through, its amplitude spectrum, the
// envelope fitted to it, and a record run's fit and critical scale. Written here, beside the
// other writers, so that every command (record, simulate --record, check, floors) writes a
// record the same way.

#include "core/check/RecordAnalysis.h"
#include "core/excitation/FloorFilter.h"
#include "core/excitation/FourierSpectrum.h"
#include "core/records/Accelerogram.h"
#include "core/sweep/CriticalAmplitude.h"

#include <nlohmann/json.hpp>

#include <cstddef>

namespace kinstab {

// file, format, names, npts, dt, duration, file units, peak and the header's peak (or null).
nlohmann::json accelerogramJson(const Accelerogram& a);
// period_s, damping, tail_s.
nlohmann::json floorFilterJson(const FloorFilterParams& p);
// points, df_hz and the count largest peaks (frequency_hz, amplitude).
nlohmann::json spectrumJson(const AmplitudeSpectrum& s, std::size_t count);
// The envelope fitted to the motion with its characteristic times in s, or {"error": why}.
nlohmann::json envelopeFitJson(const Accelerogram& motion);
// A record run's envelope fit (or {"error": why}) and its critical scale (the run must have
// searched one: a.critical set).
nlohmann::json recordFitJson(const RecordAnalysis& a);
nlohmann::json recordCriticalJson(const RecordAnalysis& a, const CriticalSearch& s);

} // namespace kinstab
