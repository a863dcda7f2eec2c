// The manual page igds(1) and the bash completion of the command line, generated from the
// declarations they describe (the command table of commands/command.h, the options of
// interp/command_line.h), so that neither can disagree with igds. interp/docs_main.cpp writes
// them at build time; CMakeLists.txt installs them.
#pragma once

#include <string>

namespace igds {

// igds.1 in the man(7) macros: NAME, SYNOPSIS, DESCRIPTION, OPTIONS, COMMANDS, FILES,
// ENVIRONMENT, EXIT STATUS, EXAMPLES, SEE ALSO. `date` is the page's date (YYYY-MM-DD).
std::string manual_page(const std::string& version, const std::string& date);

// igds-tek.1: the launcher that opens igds in the Tek window of a new xterm.
std::string launcher_page(const std::string& version, const std::string& date);

// The completion of igds's command line for bash (share/bash-completion/completions/igds):
// options, their values, the device words, command files (*.igds).
std::string bash_completion();

}  // namespace igds
