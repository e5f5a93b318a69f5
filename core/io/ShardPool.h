// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The shards of a merge, each with its line in hand, read with at most as many descriptors open
// as the process may hold (RLIMIT_NOFILE, less a reserve for the output and the standard
// streams): when a shard that was released must read on, the shard used longest ago releases
// its descriptor first (core/base/LineReader.h reopens where it stopped). Shards are in case
// order, round-robin (case % N): each is read a buffer at a time, so a release costs one reopen
// per buffer, not per line.

#include "core/io/StudyResults.h"

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace kinstab {

class ShardPool {
public:
    explicit ShardPool(const std::vector<std::string>& paths); // throws StudyRowError
    bool next(std::size_t k); // shard k's next line; false at its end
    const StudyLine& line(std::size_t k) const { return shards_[k]->line(); }
    void readToEnd(); // reads every shard to its end: a shard out of case order throws

private:
    void use(std::size_t k); // makes room for shard k's descriptor, marks it used last

    std::vector<std::unique_ptr<StudyRowReader>> shards_;
    std::vector<std::uint64_t> lastUse_;
    std::set<std::pair<std::uint64_t, std::size_t>> open_; // regular files holding a descriptor
    std::uint64_t clock_ = 0;
    std::size_t budget_ = 1;
};

// Descriptors a merge may hold open for its shards: the soft RLIMIT_NOFILE less a reserve.
std::size_t shardDescriptorBudget();

} // namespace kinstab
