// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A study (docs/studies.md): a suite of records crossed with lists of slab and floor parameters,
// each case asking for the intensity at which the record, scaled, first collapses the slab.
// The study file (versioned JSON, read by core/io/StudySpecJson.h) names every bad field in a
// StudyError ("parameters.mu[2] = -1: must be > 0").

#include "core/building/FloorSettings.h"
#include "core/building/ModalModel.h"
#include "core/codes/Building.h"
#include "core/records/Accelerogram.h"
#include "core/study/StudyBlock.h"
#include "core/sweep/CriticalAmplitude.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace kinstab {

struct StudyError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline constexpr const char* kStudyFormat = "kinstab-study";
inline constexpr int kStudyVersion = 1;

// Sizes a study file may ask for: 10,000 records is several complete strong-motion databases;
// 1,000 values of one parameter is finer than any design question; ten million cases keeps the
// case index exact and a study a matter of cluster-days, not years.
inline constexpr std::size_t kMaxStudyRecords = 10'000;
inline constexpr std::size_t kMaxStudyListValues = 1'000;
inline constexpr std::size_t kMaxStudyCases = 10'000'000;
// A record's scale in the suite: scaling to a target spectrum uses factors of about 0.2 to 5;
// a factor of 100 turns a 0.01 g record into 1 g, beyond any suite's need.
inline constexpr double kMaxStudyRecordScale = 100.0;
// Samples of all the suite's records together, held in memory for the whole study (each record
// is read once: core/study/StudyRecords.h): 10,000 records of 25,000 samples (125 s at 200
// samples/s, longer than most strong-motion records), 2 GB as doubles.
inline constexpr std::size_t kMaxStudySuiteSamples = 250'000'000;

// The intensity measure a critical scale is expressed in: the peak ground acceleration of the
// record, or its 5 %-damped spectral acceleration at a period (peak absolute acceleration of a
// linear oscillator on the ground record, Nigam & Jennings 1969).
struct IntensityMeasure {
    enum class Kind { Pga, Sa } kind = Kind::Pga;
    double period = 1.0;   // s, Sa only
    double damping = 0.05; // Sa only
};
std::string
intensityName(const IntensityMeasure& im); // "pga", "sa(1s/5%)" (no comma: it is a CSV cell)

// One record of the suite, resolved to a file (folders are expanded when the study is read).
struct StudyRecord {
    std::string file;  // absolute path
    std::string label; // the path as the study file writes it (relative to it, or absolute)
    double scale = 1;  // the record as given in the suite is the file times this
    // Once read (core/study/StudyRecords.h): the SHA-256 of the file's bytes and, for a run,
    // the ground motion parsed from those same bytes, which every case of the record uses.
    std::string sha256;
    std::shared_ptr<const Accelerogram> ground;
    // With a building: every level's motion under ground, built once when the record is read
    // and shared by every case at a level (issue 34: each case built all of them for its one).
    std::shared_ptr<const std::vector<Accelerogram>> levelMotions;
};

struct FloorFilterChoice {
    double period = 1.0; // s
    double damping = 0.02;
};

// The multi-storey model whose levels may drive the slab: the project's building as a shear
// building (core/building/ShearBuilding.h) with its floor settings' stiffness profile and modal
// damping, and its modes computed once when the study is read.
struct StudyBuilding {
    Building building;
    FloorSettings settings;
    ModalModel model;
};

// What drives the slab in a case: the motion itself, or the enveloped sine whose envelope is
// fitted to it (core/excitation/EnvelopeFit.h) at its dominant frequency.
enum class StudyMotion { Record, FittedSine };
std::string motionName(StudyMotion m);                              // "record" | "fitted_sine"
std::optional<StudyMotion> motionFromName(const std::string& name); // none: another name

struct StudySpec {
    std::string name;
    std::vector<StudyRecord> records; // in the order of the file, folders sorted by name
    bool asGiven = false; // a record entry gives "scale": rows compare with the record as given
    IntensityMeasure intensity;
    std::vector<double> mu;
    std::vector<double> tstar;                            // s (from wall_width_in when given)
    std::vector<std::optional<FloorFilterChoice>> floors; // none: the record drives the slab
    std::optional<StudyBuilding> building;
    std::vector<int> levels; // 1-based levels of the building, crossed beside the floor filters
    std::vector<StudyMotion> motions = {StudyMotion::Record};
    bool motionGiven = false; // parameters.motion is in the file: rows name their motion
    // "polarity": "both" runs every record as given and inverted (each sample's sign flipped) as
    // two cases, the SLAMMER convention for a suite (Jibson & Jibson 2003); rows then name their
    // polarity. "normal" (the default) runs each record once, as older study files did.
    bool bothPolarities = false;
    double limit = 1.0; // slab.limit, bearing length / (d/2)
    // A free-standing block instead of the slab (core/study/StudyBlock.h): each case asks for
    // the scale at which it overturns; mu, tstar, limit and motion are then the slab's unused
    // defaults (the study file refuses them).
    std::optional<StudyBlock> block;
    CriticalSearch search;
    std::string fingerprint; // once the records are read (core/study/StudyFingerprint.h)
};

} // namespace kinstab
