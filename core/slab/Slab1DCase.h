// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One 1-DOF stability case: everything but the amplitude and frequency, which a sweep varies.

#include "core/excitation/Envelope.h"
#include "core/slab/PaperRk4Solver.h"
#include "core/slab/SlabRecorder.h"
#include "core/slab/SlabTypes.h"

#include <string>

namespace kinstab {

enum class SolverKind { Exact, Paper };
std::string solverName(SolverKind s);

struct Slab1DCase {
    Envelope envelope = Envelope::fromPreset(EnvelopePreset::Moderate);
    double tstar = 0.099; // s; the paper's "8 inch" wall
    SlabParams slab;
    SolverKind solver = SolverKind::Exact;
    double paperStepsPerPeriod = 16; // H = period / this
    TauScale scale = TauScale::TauMax;

    double tauRef() const { return envelope.tauRef(scale, tstar); }
};

// t* = sqrt(d / (2 g)) for a wall of width d (docs/theory.md §2).
double tstarFromWallWidth(double wallWidthMetres);
double tstarFromWallWidthInches(double inches);
double wallWidthFromTstar(double tstar); // m: d = 2 g t*², the inverse of tstarFromWallWidth

// The first input out of its range, named by its key (core/slab/SlabInputs.h), or nothing.
InputProblem checkCase(const Slab1DCase& c);
std::string validateCase(const Slab1DCase& c); // empty when fine

// A result whose numbers are all finite, or a Failed one (see FiniteResult.h); never throws
// for a valid case. recorder: what is kept beyond it (core/slab/SlabRecorder.h); null: nothing.
SlabResult runSlab1D(const Slab1DCase& c, double amplitude, double frequencyHz,
                     const RunOptions& options = {}, SlabRecorder* recorder = nullptr);

// The case and point in words, for messages ("slab1d exact solver, A = 3 g, f = 30 Hz, ...").
std::string caseName(const Slab1DCase& c, double amplitude, double frequencyHz);

// gamma_c = tau_ref / tau_c, 0 when the slab does not collapse.
double collapseFactor(double tauRef, const SlabResult& r);

} // namespace kinstab
