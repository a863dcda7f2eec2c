#include <cctype>

#include "commands/command.h"

namespace igds {

namespace {

bool starts_with_ignoring_case(std::string_view word, std::string_view typed) {
  if (typed.empty() || typed.size() > word.size()) return false;
  for (std::size_t j = 0; j < typed.size(); ++j) {
    if (std::toupper(static_cast<unsigned char>(typed[j])) !=
        std::toupper(static_cast<unsigned char>(word[j])))
      return false;
  }
  return true;
}

}  // namespace

// The manual's LUT: the first row of the table that matches the typed letters up to their length.
const Choice* choose(std::span<const Choice> choices, std::string_view typed) {
  for (const Choice& c : choices)
    if (starts_with_ignoring_case(c.word, typed)) return &c;
  return nullptr;
}

const Command* find_command(std::string_view typed) {
  for (const Command* c : command_table())
    if (starts_with_ignoring_case(c->name, typed)) return c;
  return nullptr;
}

}  // namespace igds
