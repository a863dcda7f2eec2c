// An IGDS command declares its words, options, questions, help texts and handler once
// (docs/architecture.md, "The command declarations"). The interpreter, HELP, completion, the
// 2250 menu, the manual page and the abbreviation table are all generated from these records,
// never written a second time.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "commands/context.h"
#include "workspace/error.h"

namespace igds {

struct Command {
  std::string_view name;
  std::span<const Choice> options;  // lookup order = this order; empty: no option
  std::string_view follows;         // without options: what may follow the word, e.g. "[name]"
  Prompt option_prompt;             // asked when the option is not on the command line
  // The report for a word that is none of the options (the manual's, which differ by command).
  const char* bad_option = reports::incorrect_choice;
  std::string_view summary;    // what the command does, in one short line
  std::string_view long_help;  // a designer's explanation, with an example entry
  // The questions it may ask after its option, in order (HELP, the manual page).
  std::span<const Prompt* const> questions;
  // `option` is one of `options` (nullptr for a command without options). Words after the
  // option on the command line are unread words of `ctx`. Changes the workspace only when it
  // succeeds.
  void (*run)(Context& ctx, const Choice* option);
};

// The commands in lookup order: the manual's (BUILD CHANGE RESTORE DISPLAY PLOT STORE SAVE WRITE
// END HELP), then the project's additions, so every abbreviation of the manual keeps its meaning.
std::span<const Command* const> command_table();

// The command whose name starts with `typed` (first in table order), or nullptr.
const Command* find_command(std::string_view typed);

// How HELP is asked for at any question: the word HELP and its lengths (SHORT, LONG), from the
// HELP command's declaration. `length` of the words typed: 0 SHORT, 1 LONG, -1 not HELP, and
// `set` true when the length was typed (HELP SHORT and HELP LONG change the setting).
struct HelpRequest {
  bool asked = false;
  int length = -1;  // 0 SHORT, 1 LONG, -1 the setting in force
};
HelpRequest help_request(std::span<const std::string_view> words);
std::span<const Choice> help_lengths();
std::string_view help_word();

// The overview HELP LONG gives at READY, made from the declarations: what IGDS is, every
// command with its options and what follows them, the abbreviation rule, a small session.
std::string_view help_overview();

// What may be typed, as HELP LONG and the manual page show it: one line per group of options
// that take the same words after them, e.g. "DISPLAY FIRST|SECOND", "DISPLAY FILE [name]",
// "DISPLAY INPUT|SURFACE [projection [parameters]]".
std::vector<std::string> command_syntax(const Command& command);

}  // namespace igds
