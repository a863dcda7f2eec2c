// An IGDS command declares its words, prompts, help texts and handler once (style.md). HELP
// SHORT/LONG, completion and the abbreviation table are all generated from these records.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "commands/context.h"

namespace igds {

struct Command {
  std::string_view name;
  std::vector<std::string_view> options;  // lookup order = this order; empty: no option
  Prompt option_prompt;                   // asked when the option is not on the command line
  std::string_view short_help;            // one or two lines: what the command does
  std::string_view long_help;             // a designer's explanation, with an example entry
  // `option` indexes `options` (-1 for a command without options). Words after the option on
  // the command line are unread words of `ctx`. Changes the workspace only when it succeeds.
  void (*run)(Context& ctx, int option);
};

// The commands in lookup order: the manual's (BUILD CHANGE RESTORE DISPLAY PLOT STORE SAVE WRITE
// END HELP), then the project's additions (ERASE EXPORT), so every abbreviation of the manual
// keeps its meaning.
std::span<const Command* const> command_table();

// The first entry of `words` (in order) that starts with `typed`, case ignored; -1 when none
// does or `typed` is empty or longer than every match (spec igds.md section 2).
int lookup_prefix(std::span<const std::string_view> words, std::string_view typed);

}  // namespace igds
