// The command line of igds (docs/interp.md, "Command line") and the choice of the terminal mode
// (docs/devices.md, "Tektronix 4013").
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "commands/context.h"

namespace igds {

// A command line igds does not understand: the message, then the usage, exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CommandLine {
  Options options;                  // disk and term are resolved by resolve_command_line
  std::optional<std::string> disk;  // --disk DIR
  std::optional<TermMode> term;     // --term
  std::vector<std::string> files;   // command files, in order
  bool then_interactive = false;    // `-` after the files
  bool device_2250 = false;         // `igds 2250`
  bool help = false, version = false;
};

// Parses argv[1..]. Throws UsageError.
CommandLine parse_command_line(const std::vector<std::string>& args);

// The automatic terminal mode, first rule that applies: stdout not a terminal -> tek; TERM
// starting with "tek" -> tek; XTERM_VERSION set and TERM=dumb (xterm -t without a tek4014
// terminfo entry) -> tek; XTERM_VERSION set -> xterm; else none.
TermMode choose_term(bool stdout_is_terminal, const char* term_env, const char* xterm_version);

// The usage message (--help, and after a usage error).
std::string usage_text();

// The options, for the manual page and the shell's completion (interp/manual.h): each name, the
// word that stands for its value in the usage ("" when it takes none) and the values it takes
// when they are a fixed list. parse_command_line accepts exactly these.
struct OptionSpec {
  std::string_view name;
  std::string_view value;
  std::vector<std::string_view> values;
};
const std::vector<OptionSpec>& command_line_options();

}  // namespace igds
