#include <cctype>

#include "commands/command.h"

namespace igds {

// The manual's LUT: the first row of the table that matches the typed letters up to their length.
int lookup_prefix(std::span<const std::string_view> words, std::string_view typed) {
  if (typed.empty()) return -1;
  for (std::size_t i = 0; i < words.size(); ++i) {
    std::string_view word = words[i];
    if (typed.size() > word.size()) continue;
    bool match = true;
    for (std::size_t j = 0; j < typed.size() && match; ++j) {
      match = std::toupper(static_cast<unsigned char>(typed[j])) ==
              std::toupper(static_cast<unsigned char>(word[j]));
    }
    if (match) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace igds
