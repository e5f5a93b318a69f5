// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The cases of a study in their fixed order (docs/studies.md): parameter sets (mu, then t*, then
// the driver - the floor filters, then the building's levels - then the motion, the last varying
// fastest) on the outside, records inside (with polarity "both", each record as given and then
// inverted), so that the records of one parameter set - one fragility curve - are neighbours. A
// case is found from its index alone: no list of cases is ever built, so a study of millions of
// cases takes no memory for it.

#include "core/study/StudyRow.h"
#include "core/study/StudySpec.h"

#include <cstddef>
#include <optional>
#include <string>

namespace kinstab {

struct StudyCase {
    std::size_t index = 0; // 0-based position in the study
    std::size_t set = 0;   // parameter set (index / records)
    const StudyRecord* record = nullptr;
    double mu = 0, tstar = 0;
    std::optional<FloorFilterChoice> floor;
    int level = 0; // > 0: this level of the study's building drives the slab (floor is none)
    StudyMotion motion = StudyMotion::Record;
    bool inverted = false; // the record with every sample's sign flipped (polarity "both")
};

std::size_t studyCaseCount(const StudySpec& s);
std::size_t studyParameterSets(const StudySpec& s);
// Cases per parameter set: the records, twice with polarity "both".
std::size_t studyCasesPerSet(const StudySpec& s);
StudyCase studyCase(const StudySpec& s, std::size_t index); // index < studyCaseCount
// The inputs a case's row carries (index, the study's fingerprint, set, record, mu, t*, limit,
// floor filter or level, motion when the study names motions, measure): what a run writes and
// what a results file is checked against (core/study/StudyRowsMatch.h).
StudyRow studyRowInputs(const StudySpec& s, const StudyCase& c);

// A shard K of N (1-based) takes every case whose index % N == K - 1: round-robin spreads the
// slow records and high limits evenly over the shards.
struct Shard {
    std::size_t k = 1, n = 1;
    bool owns(std::size_t index) const { return index % n == k - 1; }
};
// "K/N" with 1 <= K <= N <= kMaxStudyCases; nothing on any other text.
std::optional<Shard> parseShard(const std::string& text);

} // namespace kinstab
