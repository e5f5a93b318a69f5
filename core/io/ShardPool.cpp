// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/ShardPool.h"

#include "core/base/LineReader.h"

#include <sys/resource.h>

#include <algorithm>

namespace kinstab {

namespace {

// Descriptors kept free for everything else a merge has open: the standard streams, the output
// and its folder, a --list file, the C library's own.
constexpr std::size_t kReservedDescriptors = 24;

// A buffer per shard: 64 KiB each up to 64 shards, then 4 MiB shared (4 KiB at least; a
// merge of 1000 shards took 150 MB with 64 KiB each, 26 MB with std::ifstream's 8 KiB).
std::size_t chunkFor(std::size_t shards) {
    if (shards <= 64) return 64u * 1024u;
    return std::max<std::size_t>(4096, (4u << 20) / shards);
}

} // namespace

std::size_t shardDescriptorBudget() {
    rlimit limit{};
    if (::getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return 1024;
    const auto soft = static_cast<std::size_t>(limit.rlim_cur);
    return soft > kReservedDescriptors + 1 ? soft - kReservedDescriptors : 1;
}

ShardPool::ShardPool(const std::vector<std::string>& paths)
    : lastUse_(paths.size(), 0), budget_(shardDescriptorBudget()) {
    const std::size_t chunk = chunkFor(paths.size());
    for (std::size_t k = 0; k < paths.size(); ++k) {
        use(k); // room for the descriptor the reader opens
        shards_.push_back(std::make_unique<StudyRowReader>(paths[k], chunk));
        if (shards_[k]->file().regular()) open_.insert({lastUse_[k], k});
    }
}

void ShardPool::use(std::size_t k) {
    const bool held = k < shards_.size() && shards_[k]->file().isOpen();
    if (held) open_.erase({lastUse_[k], k});
    // Each pass releases one descriptor: bounded by the shards holding one.
    while (!held && !open_.empty() && open_.size() >= budget_) {
        const std::size_t oldest = open_.begin()->second;
        shards_[oldest]->file().suspend();
        open_.erase(open_.begin());
    }
    lastUse_[k] = ++clock_;
    if (held) open_.insert({lastUse_[k], k});
}

bool ShardPool::next(std::size_t k) {
    use(k);
    const bool more = shards_[k]->next();
    LineReader& file = shards_[k]->file();
    if (!more && file.regular()) { // a shard read to its end needs its descriptor no more
        file.suspend();
        open_.erase({lastUse_[k], k});
    }
    // A reader reopens its file inside next(): from then on it holds a descriptor.
    if (file.regular() && file.isOpen()) open_.insert({lastUse_[k], k});
    return more;
}

void ShardPool::readToEnd() {
    for (std::size_t k = 0; k < shards_.size(); ++k)
        while (next(k)) {
        }
}

} // namespace kinstab
