// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One planar stability case (Furgerson 1980, ch. VI; docs/theory.md §5): everything but the
// across-wall amplitude A_x and frequency f_x, which a sweep varies (Figs. 37-42). a_y is an
// enveloped sine with A_y = ratio A_x and its own f_y; the vertical factor n = 1 + a_z takes any
// motion.

#include "core/excitation/Envelope.h"
#include "core/excitation/Excitation1D.h"
#include "core/slab/PlanarSolver.h"
#include "core/slab/PointResult.h"
#include "core/slab/Slab1DCase.h"

#include <memory>
#include <optional>
#include <string>

namespace kinstab {

// How each horizontal component's S_max is taken. Product (default, ch. IV): the maximum of
// envelope x sine, so each component peaks at its amplitude. Envelope (as printed in ch. VI):
// the maximum of the envelope alone, so each peaks somewhat below its amplitude.
enum class PlanarNormalization { Product, Envelope };
std::string normalizationName(PlanarNormalization n);
std::optional<PlanarNormalization> normalizationFromName(const std::string& name);

// What the planar model adds to the 1-DOF case: the along-wall limit, the motion along the walls,
// the vertical motion and its own solver's tolerances.
struct PlanarInputs {
    double theta = 20.0; // along the walls: collapse when |dy| > theta = 2 wall length / wall width
    double ayRatio = 0.9; // A_y / A_x (the paper: Pacoima Dam's ratio of horizontal peaks)
    double fyHz = 1.0;    // frequency along the walls
    PlanarNormalization normalization = PlanarNormalization::Product;
    std::shared_ptr<const Excitation1D> vertical; // upward base acceleration a_z in g; null: none
    PlanarOptions solver;
};

// The 1-DOF case (envelope, t*, scale, mu, limit, duration: held once, in `common`) and the
// planar model's own inputs. common's solver fields are the 1-DOF solvers' and unused here.
struct PlanarCase : PlanarInputs {
    Slab1DCase common;

    PlanarCase() = default;
    PlanarCase(const Slab1DCase& shared, const PlanarInputs& own)
        : PlanarInputs(own), common(shared) {}

    double tauRef() const { return common.tauRef(); }
    PlanarParams params() const { return {common.slab, theta}; } // of the model
    const PlanarInputs& own() const { return *this; }
};

InputProblem checkPlanarCase(const PlanarCase& c);   // the first input out of range, or nothing
std::string validatePlanarCase(const PlanarCase& c); // empty when fine

// The model of one grid point, sharing the case's vertical motion.
SlabModel2D planarModel(const PlanarCase& c, double ax, double fxHz);
// recorder: what is kept beyond the result (core/slab/PlanarRecorder.h); null: nothing.
PlanarResult runPlanar(const PlanarCase& c, double ax, double fxHz,
                       PlanarRecorder* recorder = nullptr);
PointFunction planarPoint(const PlanarCase& c);
// Below this A_x nothing can slip: |a_h| <= A_x sqrt(1 + ratio^2) < mu min n (each component
// peaks at most at its amplitude). Where a critical-amplitude scan may start.
double planarNoSlipAmplitude(const PlanarCase& c);

} // namespace kinstab
