// Reading the user's answers: whole numbers, yes or no, file names; and the rule every question
// follows: a bad answer typed at the question gets its report and the question again, while one
// that was on the command line ends the command with the report, as the manual does.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "commands/context.h"
#include "workspace/error.h"

namespace igds {

// A whole number written as a number word (`3`, `3.0`, `3E0`), within [low, high].
std::optional<long long> parse_integer(std::string_view word, long long low, long long high);

// YES and NO (any prefix): the answers of the CHANGE chain's questions.
std::span<const Choice> yes_no();
// True for yes, false for no; nullopt when the words are not one of them.
std::optional<bool> parse_yes_no(std::span<const std::string_view> words);

// Asks `prompt` until `parse` (words -> value, or throws Error) accepts a non-empty reply.
template <class Parse>
auto ask_for(Context& ctx, const Prompt& prompt, Parse parse) {
  for (;;) {
    const bool on_the_line = ctx.pending_from_command_line();
    std::vector<std::string> words = ctx.ask(prompt);
    if (words.empty()) continue;
    try {
      return parse(words);
    } catch (const Error& e) {
      if (on_the_line) throw;
      ctx.report(e.what());
    }
  }
}

// The CMS name (in capitals) of the next reply to `prompt`, asked again while the reply typed
// there is not exactly one CMS name (INCORRECT PARAMETER with the rule).
std::string ask_file_name(Context& ctx, const Prompt& prompt);

// The reason given with INCORRECT PARAMETER for a name that is not a CMS name.
inline constexpr std::string_view name_rule = "A NAME HAS 1 TO 8 LETTERS, DIGITS OR $ # @ + - _";

// Throws `report` (INCORRECT COMMAND OR PARAMETERS unless the command's manual says otherwise)
// when words are left on the command line.
void expect_no_more_words(Context& ctx, const char* report = reports::incorrect_command);

// When `word` is the name of a command (at least two letters of it), the reason an entry prompt
// gives for it: "DISPLAY IS A COMMAND: END THE ENTRIES WITH AN EMPTY LINE FIRST"; else "".
std::string command_word_reason(std::string_view word, std::string_view how_to_finish);

}  // namespace igds
