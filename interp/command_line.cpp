#include "interp/command_line.h"

#include <string_view>

namespace igds {

namespace {

std::optional<TermMode> term_named(std::string_view name) {
  if (name == "xterm") return TermMode::xterm;
  if (name == "tek") return TermMode::tek;
  if (name == "none") return TermMode::none;
  return std::nullopt;
}

}  // namespace

std::string usage_text() {
  return R"(usage: igds [4013|2250] [options] [FILE ...] [-]

Interactive Design of Interpolated Surfaces. FILEs are command files, read as if
typed; igds ends after the last one unless - follows (then it goes on with the
terminal). Standard input that is not a terminal is read as a command file.

options:
  --disk DIR             the user's disk, where every file lives
                         (default: $IGDS_DISK, else the current directory)
  --term xterm|tek|none  how images reach the terminal (default: chosen from the
                         environment: tek when output is not a terminal or TERM
                         is tek*, xterm under xterm, else none)
  --tek 4013|4014        Tektronix resolution: 1024 x 780 or 4096 x 3120
  --plotter PATH         where PLOT sends HP-GL: a file or device, or tty for a
                         plotter on the terminal line (default: PLOTnnnn.HPGL files)
  --paper A4|A3|LETTER|B the plotter's paper (default A4)
  --strict               stop at the first error in a command file, exit status 3
  --help, --version
)";
}

const std::vector<OptionSpec>& command_line_options() {
  static const std::vector<OptionSpec> options{
      {"--disk", "DIR", {}},
      {"--term", "MODE", {"xterm", "tek", "none"}},
      {"--tek", "MODEL", {"4013", "4014"}},
      {"--plotter", "PATH", {}},
      {"--paper", "SIZE", {"A4", "A3", "LETTER", "B"}},
      {"--strict", "", {}},
      {"--help", "", {}},
      {"--version", "", {}},
  };
  return options;
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine line;
  bool options_done = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i];
    if (line.then_interactive) throw UsageError("- must be the last argument");
    if (i == 0 && (arg == "4013" || arg == "2250")) {
      line.device_2250 = arg == "2250";
      continue;
    }
    if (options_done || arg == "-" || !arg.starts_with("--")) {
      if (arg == "-" && !options_done) {
        line.then_interactive = true;
      } else if (arg.starts_with("-") && arg != "-" && !options_done) {
        throw UsageError("unknown option " + arg);
      } else {
        line.files.push_back(arg);
      }
      continue;
    }
    if (arg == "--") {
      options_done = true;
      continue;
    }
    // --name=value or --name value
    std::string name = arg, value;
    bool has_value = false;
    if (auto eq = arg.find('='); eq != std::string::npos) {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
      has_value = true;
    }
    auto take_value = [&]() -> std::string {
      if (has_value) return value;
      // An option word next is a forgotten value (`--disk --term none`), not a folder's name;
      // `--disk=--odd` still names one.
      if (i + 1 >= args.size() || args[i + 1].starts_with("--"))
        throw UsageError(name + " needs a value");
      return args[++i];
    };
    if (name == "--help" && !has_value) {
      line.help = true;
    } else if (name == "--version" && !has_value) {
      line.version = true;
    } else if (name == "--strict" && !has_value) {
      line.options.strict = true;
    } else if (name == "--disk") {
      line.disk = take_value();
      if (line.disk->empty()) throw UsageError("--disk needs a folder");
    } else if (name == "--term") {
      auto mode = term_named(take_value());
      if (!mode) throw UsageError("--term is xterm, tek or none");
      line.term = mode;
    } else if (name == "--tek") {
      auto model = take_value();
      if (model == "4013")
        line.options.tek.bits = 10;
      else if (model == "4014")
        line.options.tek.bits = 12;
      else
        throw UsageError("--tek is 4013 or 4014");
    } else if (name == "--plotter") {
      line.options.plotter = take_value();
      if (line.options.plotter.empty()) throw UsageError("--plotter needs a path");
    } else if (name == "--paper") {
      auto paper = paper_named(take_value());
      if (!paper) throw UsageError("--paper is A4, A3, LETTER or B");
      line.options.plot.paper = *paper;
    } else {
      throw UsageError("unknown option " + arg);
    }
  }
  return line;
}

TermMode choose_term(bool stdout_is_terminal, const char* term_env, const char* xterm_version) {
  if (!stdout_is_terminal) return TermMode::tek;
  const std::string_view term = term_env ? term_env : "";
  if (term.starts_with("tek")) return TermMode::tek;
  // xterm -t sets TERM to tek4014, or to dumb where terminfo has no tek4014 entry: either way
  // the user is in the Tek window already.
  if (xterm_version && term == "dumb") return TermMode::tek;
  if (xterm_version) return TermMode::xterm;
  return TermMode::none;
}

}  // namespace igds
