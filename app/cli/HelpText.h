// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What kinstab-cli prints for --help, COMMAND --help and --version: one table of texts, so
// the man page, the bash completion and the tests read the same list of commands.

#include <string>
#include <vector>

namespace kinstab::cli {

struct CommandHelp {
    const char* name;    // the subcommand, as typed
    const char* summary; // one line, for the overview
    const char* text;    // the flags, with units and defaults
};

const std::vector<CommandHelp>& commandHelps();
// The overview: every command with its summary, and where to read more.
std::string usageText();
// "usage: kinstab-cli NAME ..." and the flags; empty when NAME is no command.
std::string commandHelpText(const std::string& name);
// "kinstab-cli 0.1.0" and the licence line.
std::string versionText();

} // namespace kinstab::cli
