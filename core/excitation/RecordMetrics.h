// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What an accelerogram is, in the numbers a record catalogue lists and searches by (SLAMMER,
// PEER NGA): peak ground acceleration, velocity and displacement, Arias intensity, significant
// duration D5-95, mean period Tm and the 5 %-damped spectral acceleration at the building's
// period. Computed once when a record is read (Records tab, study record table, `kinstab-cli
// record`, Python's read_record).
//
// Integration: the acceleration is linear between samples (as the solver and the floor filter
// take it), and velocity, displacement, the Arias integral and the oscillator are integrated
// exactly for that shape, from rest. No baseline correction is applied: the files kinstab reads
// (PEER NGA AT2, COSMOS and CSMIP V2) are processed, baseline-corrected records, and a
// correction of our own would change their PGV and PGD away from the published ones. The
// velocity left at the end (`finalVelocity`) shows how much drift an uncorrected file carries.
//
// Sources: Arias, A. (1970), "A measure of earthquake intensity", in Hansen (ed.), Seismic Design
// for Nuclear Power Plants, MIT Press, 438-483; Trifunac, M.D. & Brady, A.G. (1975), "A study on
// the duration of strong earthquake ground motion", BSSA 65(3), 581-626; Rathje, E.M.,
// Abrahamson, N.A. & Bray, J.D. (1998), "Simplified frequency content estimates of earthquake
// ground motions", J. Geotech. Geoenviron. Eng. 124(2), 150-159; Nigam, N.C. & Jennings, P.C.
// (1969), "Calculation of response spectra from strong-motion earthquake records", BSSA 59(2).

#include "core/records/Accelerogram.h"

#include <optional>

namespace kinstab {

// The damping of the spectral acceleration a catalogue lists (and hazard curves use).
inline constexpr double kSpectralDamping = 0.05;

struct SpectralAcceleration {
    double period = 0;  // s
    double damping = 0; // fraction of critical
    double g = 0;       // max |absolute acceleration| of the oscillator, g
};

struct RecordMetrics {
    double pga = 0;           // g, max |a|
    double pgv = 0;           // m/s, max |v|
    double pgd = 0;           // m, max |d|
    double finalVelocity = 0; // m/s, v at the last sample (drift of an uncorrected record)
    double arias = 0;         // m/s, Ia = pi / (2 g) * integral of a^2 dt (Arias 1970)
    // Significant duration: from 5 % to 95 % of the Arias integral (Trifunac & Brady 1975), s;
    // none for a record of zeros.
    std::optional<double> t5, t95, d5_95;
    // Mean period (Rathje, Abrahamson & Bray 1998, eq. 4): sum C^2/f / sum C^2 over the Fourier
    // amplitudes C with 0.25 <= f <= 20 Hz, s; none when that band holds no energy.
    std::optional<double> meanPeriod;
    std::optional<SpectralAcceleration> sa; // at the period asked for, when one was
};

// Spectral acceleration (g): the peak absolute acceleration of a linear oscillator of `period` s
// and `damping` on the record, from rest over the record's samples (no free-vibration tail), by
// the exact Nigam-Jennings recurrence (core/excitation/FloorFilter.h) - the same Sa as a study's
// intensity measure "sa" (core/study/StudyRunner.cpp), so the two compare. (Not the
// pseudo-acceleration w^2 max|x|, which leaves out the damping force.) Throws std::invalid_argument
// for a period or damping the floor filter refuses.
double spectralAcceleration(const Accelerogram& a, double period, double damping);

// Every metric above; `saPeriod` (s) adds Sa(T, 5 %). The accelerogram must be valid
// (validateAccelerogram).
RecordMetrics recordMetrics(const Accelerogram& a, std::optional<double> saPeriod = std::nullopt);

} // namespace kinstab
