// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/Suggest.h"

#include "app/cli/HelpText.h"

#include <algorithm>
#include <cctype>

namespace kinstab::cli {

std::size_t editDistance(const std::string& a, const std::string& b) {
    // Optimal string alignment: rows i-2, i-1 and i of the usual table.
    const std::size_t n = b.size();
    std::vector<std::size_t> before(n + 1), previous(n + 1), row(n + 1);
    for (std::size_t j = 0; j <= n; ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        row[0] = i;
        for (std::size_t j = 1; j <= n; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                row[j] = std::min(row[j], before[j - 2] + 1);
        }
        before.swap(previous);
        previous.swap(row);
    }
    return previous[n];
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t bestDistance = 3; // 2 edits at most
    for (const std::string& c : candidates) {
        const std::size_t d = editDistance(word, c);
        if (d < bestDistance && 2 * d < std::max<std::size_t>(word.size(), 2)) {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}

namespace {
// "--name" appears in text followed by something that cannot continue a flag's name.
bool mentionsFlag(const std::string& text, const std::string& flag) {
    const std::string token = "--" + flag;
    for (std::size_t at = text.find(token); at != std::string::npos;
         at = text.find(token, at + 1)) {
        const std::size_t end = at + token.size();
        const bool whole =
            end == text.size() ||
            !(std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-');
        const bool starts = at == 0 || text[at - 1] != '-';
        if (whole && starts) return true;
    }
    return false;
}
} // namespace

std::vector<std::string> commandsWithFlag(const std::string& flag) {
    std::vector<std::string> out;
    for (const CommandHelp& c : commandHelps())
        if (mentionsFlag(c.text, flag)) out.emplace_back(c.name);
    return out;
}

std::vector<std::string> commandNames() {
    std::vector<std::string> out;
    for (const CommandHelp& c : commandHelps())
        out.emplace_back(c.name);
    return out;
}

} // namespace kinstab::cli
