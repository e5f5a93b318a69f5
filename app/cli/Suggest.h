// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Did you mean ...?" for a misspelt command or flag, and which commands own a flag given to
// another one, read from the help texts (app/cli/HelpText.h) so that the list is never stale.

#include <string>
#include <vector>

namespace kinstab::cli {

// Levenshtein distance (insert, delete, substitute, and swap of two neighbours: "chcek").
std::size_t editDistance(const std::string& a, const std::string& b);
// The candidate nearest to word, when near enough to be a slip (at most 2 edits, and fewer than
// half of word's letters); "" otherwise.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);
// The commands whose help lists --flag ("amplitudes" -> surface, bench).
std::vector<std::string> commandsWithFlag(const std::string& flag);
// The names of all commands.
std::vector<std::string> commandNames();

} // namespace kinstab::cli
