// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/Slab1DCase.h"

#include "core/base/NameTable.h"

#include "core/base/InternalError.h"
#include "core/base/PhysicalConstants.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/slab/ExactSolver.h"
#include "core/slab/FiniteResult.h"
#include "core/slab/SlabInputs.h"

#include <cmath>
#include <numbers>
#include <sstream>

namespace kinstab {

// SolverKind's names, in its declaration order (Exact, Paper).
constexpr std::array<const char*, 2> kSolverNames = {"exact", "paper"};
static_assert(kSolverNames.size() == static_cast<std::size_t>(SolverKind::Paper) + 1);

std::string solverName(SolverKind s) {
    return enumName(kSolverNames, s);
}

double tstarFromWallWidth(double d) {
    return std::sqrt(d / (2.0 * kStandardGravity));
}
double wallWidthFromTstar(double tstar) {
    return 2.0 * kStandardGravity * tstar * tstar;
}
double tstarFromWallWidthInches(double inches) {
    return tstarFromWallWidth(inches * 0.0254);
}

InputProblem checkCase(const Slab1DCase& c) {
    if (InputProblem e = checkEnvelope(c.envelope.alpha, c.envelope.beta); !e.empty()) return e;
    if (InputProblem e = checkSlabParams(c.slab); !e.empty()) return e;
    if (InputProblem e = checkInput(kTstarInput, c.tstar); !e.empty()) return e;
    return checkInput(kPaperStepsInput, c.paperStepsPerPeriod);
}

std::string validateCase(const Slab1DCase& c) {
    return describe(checkCase(c));
}

SlabResult runSlab1D(const Slab1DCase& c, double amplitude, double frequencyHz,
                     const RunOptions& options, SlabRecorder* recorder) {
    try {
        const EnvelopedSine a(c.envelope, amplitude, frequencyHz, c.tstar);
        if (c.solver == SolverKind::Exact) return solveExact(a, c.slab, options, recorder);
        PaperSettings settings;
        settings.step = 2.0 * std::numbers::pi / a.omega() / c.paperStepsPerPeriod;
        return solvePaperRk4(a, c.slab, settings, options, recorder);
    } catch (const InternalError& e) {
        // A failed point, not an exception: sweeps run this on worker threads.
        SlabResult failed;
        failed.failure = std::string(kInternalFailure) + e.what();
        return failed;
    }
}

std::string caseName(const Slab1DCase& c, double amplitude, double frequencyHz) {
    std::ostringstream s;
    s.precision(17);
    s << "slab1d " << solverName(c.solver) << " solver, A = " << amplitude
      << " g, f = " << frequencyHz << " Hz, mu = " << c.slab.mu << ", envelope "
      << c.envelope.name() << ", t* = " << c.tstar << " s";
    return s.str();
}

double collapseFactor(double tauRef, const SlabResult& r) {
    return r.outcome == Outcome::Collapsed ? tauRef / r.tauC : 0.0;
}

} // namespace kinstab
