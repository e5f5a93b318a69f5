// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Eurocode8.h"
#include "core/codes/CodeCatalog.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kinstab {

namespace {
const char* const kGroundNames[] = {"A", "B", "C", "D", "E"};
}

std::string validateEurocode8(const Eurocode8Inputs& in) {
    std::ostringstream s;
    if (in.spectrumType != 1 && in.spectrumType != 2) {
        s << "ec8.spectrum_type = " << in.spectrumType << ": must be 1 or 2 (EN 1998-1 §3.2.2.2)";
        return s.str();
    }
    if (in.importanceClass && (*in.importanceClass < 1 || *in.importanceClass > 4)) {
        s << "ec8.importance_class = " << *in.importanceClass << ": must be 1, 2, 3 or 4 (I–IV)";
        return s.str();
    }
    try {
        requireIn("ec8.agr", in.agr, kEc8Agr, "g");
        if (in.gammaI) requireIn("ec8.gamma_i", *in.gammaI, kEc8GammaI);
        requireIn("ec8.q", in.q, kEc8Q);
        requireIn("ec8.beta", in.beta, kEc8Beta);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

std::string ec8GroundName(Ec8Ground g) {
    return kGroundNames[static_cast<int>(g)];
}

std::optional<Ec8Ground> ec8GroundFromName(const std::string& s) {
    for (int i = 0; i < 5; ++i)
        if (s == kGroundNames[i]) return static_cast<Ec8Ground>(i);
    return std::nullopt;
}

// Tables 3.2 (Type 1) and 3.3 (Type 2), recommended values (docs/codes.md §6.1).
Ec8SpectrumParameters ec8Spectrum(Ec8Ground g, int type) {
    static const Ec8SpectrumParameters t1[] = {{1.00, 0.15, 0.40, 2.0},
                                               {1.20, 0.15, 0.50, 2.0},
                                               {1.15, 0.20, 0.60, 2.0},
                                               {1.35, 0.20, 0.80, 2.0},
                                               {1.40, 0.15, 0.50, 2.0}};
    static const Ec8SpectrumParameters t2[] = {{1.00, 0.05, 0.25, 1.2},
                                               {1.35, 0.05, 0.25, 1.2},
                                               {1.50, 0.10, 0.25, 1.2},
                                               {1.80, 0.10, 0.30, 1.2},
                                               {1.60, 0.05, 0.25, 1.2}};
    return (type == 2 ? t2 : t1)[static_cast<int>(g)];
}

// Eqs. 3.13–3.16; the β a_g floor applies on the two descending branches only.
double ec8DesignSpectrum(double t, double ag, const Ec8SpectrumParameters& p, double q,
                         double beta) {
    if (t <= p.tb) return ag * p.s * (2.0 / 3.0 + t / p.tb * (2.5 / q - 2.0 / 3.0));
    if (t <= p.tc) return ag * p.s * 2.5 / q;
    if (t <= p.td) return std::max(ag * p.s * 2.5 / q * p.tc / t, beta * ag);
    return std::max(ag * p.s * 2.5 / q * p.tc * p.td / (t * t), beta * ag);
}

// §4.2.5(5)P recommended γ_I: I 0.8, II 1.0, III 1.2, IV 1.4.
double ec8ImportanceFactor(int c) {
    static const double g[] = {0.8, 1.0, 1.2, 1.4};
    return g[std::clamp(c, 1, 4) - 1];
}

// Table 4.3: ordinary buildings II; assembly and consequential contents III; civil-protection
// facilities IV.
int ec8ImportanceClass(Occupancy o) {
    return occupancyClass(o);
}

// §4.3.3.2.2(3) eq. 4.6: T_1 = C_t H^(3/4), H in m; C_t 0.085 steel moment frames, 0.075
// concrete moment frames and steel EBF, 0.050 all others. Valid for H <= 40 m.
double eurocode8FormulaPeriod(const Building& b) {
    double ct = 0.050;
    if (b.system == StructuralSystem::SteelMomentFrame)
        ct = 0.085;
    else if (b.system == StructuralSystem::ConcreteMomentFrame ||
             b.system == StructuralSystem::SteelBracedEccentric)
        ct = 0.075;
    return ct * std::pow(heightMetres(b), 0.75);
}

namespace {
void addPeriod(CodeResult& r, const Building& b) {
    if (b.period) {
        r.periodSeconds = *b.period;
        r.periodSource = "entered";
        r.trail.push_back(
            {"fundamental period (entered)", "T_1", r.periodSeconds, "§4.3.3.2.2(2)"});
        return;
    }
    r.periodSeconds = eurocode8FormulaPeriod(b);
    r.periodSource = "formula";
    r.trail.push_back({"height", "H", heightMetres(b), "m"});
    r.trail.push_back({"fundamental period", "T_1", r.periodSeconds, "§4.3.3.2.2(3) eq. 4.6"});
    if (heightMetres(b) > 40.0)
        r.notes.push_back("H > 40 m: eq. 4.6 is outside its range; enter T_1 from an analysis");
}

void checkApplicability(CodeResult& r, const Eurocode8Inputs& in, const Ec8SpectrumParameters& p) {
    const double limit = std::min(4.0 * p.tc, 2.0);
    if (r.periodSeconds > limit) {
        r.applicable = false;
        std::ostringstream s;
        s << "T_1 = " << r.periodSeconds << " s > min(4 T_C, 2.0 s) = " << limit
          << " s: the lateral force method is not applicable (§4.3.3.2.1(2)a)";
        r.notes.push_back(s.str());
    }
    if (!in.regularInElevation) {
        r.applicable = false;
        r.notes.push_back("not regular in elevation: the lateral force method is not applicable "
                          "(§4.3.3.2.1(2)b)");
    }
    if (r.periodSeconds > 4.0)
        r.notes.push_back(
            "T_1 > 4 s: the design spectrum is not defined there (eq. 3.16 extended)");
}
} // namespace

CodeResult eurocode8(const Building& b, const Eurocode8Inputs& in) {
    CodeResult r = beginCodeResult(b, validateEurocode8(in), codeInfo(CodeKey::Ec8));
    addPeriod(r, b);
    const double t = r.periodSeconds;
    const Ec8SpectrumParameters p = ec8Spectrum(in.ground, in.spectrumType);
    const int cls = in.importanceClass.value_or(ec8ImportanceClass(b.occupancy));
    const double gammaI = in.gammaI.value_or(ec8ImportanceFactor(cls));
    const double ag = gammaI * in.agr;
    const double sd = ec8DesignSpectrum(t, ag, p, in.q, in.beta);
    const double lambda = (t <= 2.0 * p.tc && b.stories > 2) ? 0.85 : 1.0;
    const double fb = sd * lambda;
    const std::string table = in.spectrumType == 1 ? "Table 3.2" : "Table 3.3";
    const std::string ground = ", ground type " + ec8GroundName(in.ground);
    r.trail.push_back({"reference peak ground acceleration", "a_gR", in.agr, "§3.2.1 (entered)"});
    r.trail.push_back({"importance class", "class", static_cast<double>(cls), "Table 4.3"});
    r.trail.push_back(
        {"importance factor", "gamma_I", gammaI, in.gammaI ? "§4.2.5 (entered)" : "§4.2.5(5)P"});
    r.trail.push_back({"design ground acceleration", "a_g", ag, "§3.2.1(3), a_g = gamma_I a_gR"});
    r.trail.push_back({"soil factor", "S", p.s, table + ground});
    r.trail.push_back({"corner period", "T_B", p.tb, table});
    r.trail.push_back({"corner period", "T_C", p.tc, table});
    r.trail.push_back({"corner period", "T_D", p.td, table});
    r.trail.push_back({"behaviour factor", "q", in.q, "§3.2.2.5, Table 5.1 / 6.2"});
    r.trail.push_back({"lower-bound factor", "beta", in.beta, "§3.2.2.5(4)P"});
    r.trail.push_back({"design spectrum", "S_d(T_1)/g", sd, "§3.2.2.5 eqs. 3.13–3.16"});
    r.trail.push_back({"correction factor", "lambda", lambda, "§4.3.3.2.2(1)"});
    r.trail.push_back({"base shear coefficient", "F_b/W", fb, "§4.3.3.2.2(1) eq. 4.5"});
    checkApplicability(r, in, p);

    r.baseShearCoefficient = fb;
    r.storyForces = distributedRatios(levelWeights(b), levelHeights(b), 1.0, fb);
    r.topRatio = r.storyForces.back();
    r.trail.push_back(
        {"top ratio", "F_n/w_n", r.topRatio, "§4.3.3.2.3(3) eq. 4.11 (linear mode shape)"});
    return r;
}

} // namespace kinstab
