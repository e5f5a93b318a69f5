// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Free rocking (no base motion) in closed form, and what energy says about it. theta, theta' as
// in RockingSolver.h; z = sgn theta.

#include "core/rocking/RockingModel.h"

namespace kinstab {

// Linearised free rocking released from rest at theta0 = r alpha (0 <= r < 1): time to the first
// impact (1/p) acosh(1 / (1 - r)) (Housner 1963, eq. 3 gives the period as four times it).
double housnerQuarterPeriod(double p, double tiltRatio);

// Energy per unit of the polar moment about the pivot, of a free block about the corner z:
// exact      E = theta'^2/2 + p^2 cos(alpha z - theta)
// linearised E = theta'^2/2 - p^2 (alpha z - theta)^2 / 2
// Constant between impacts; an impact multiplies theta'^2 by eta^2.
double rockingEnergy(RockingEquations eq, double p, double alpha, double theta, double omega);
// The energy of balance on the corner (theta = alpha z, at rest): above it the block passes.
double balanceEnergy(RockingEquations eq, double p);
// The largest |theta| of free rocking with energy E below balanceEnergy.
double freeAmplitude(RockingEquations eq, double p, double alpha, double energy);

// What free rocking from (theta, theta') does, decided by energy: it overturns, or its amplitude
// decays from the largest |theta| it will still reach (maxAbsTheta) after `impacts` more impacts
// before that amplitude (0 or 1, the one still ahead when it moves towards theta = 0).
struct FreeFate {
    bool overturns = false;
    double maxAbsTheta = 0.0; // the largest |theta| it still reaches (if it does not overturn)
};
FreeFate freeFate(RockingEquations eq, double p, double alpha, double eta, double theta,
                  double omega);

// Linearised: the amplitude after n impacts of free rocking released from rest at r alpha:
// each impact multiplies theta'^2 at theta = 0 by eta^2, so
// (1 - r_n)^2 = 1 - eta^(2n) (1 - (1 - r)^2) (energy balance, Housner 1963, sec. on free
// rocking).
double linearAmplitudeAfterImpacts(double tiltRatio, double eta, int n);

} // namespace kinstab
