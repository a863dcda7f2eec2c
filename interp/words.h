// The words of a line as IGDS reads them (spec igds.md section 2): blanks and commas separate
// words, case is ignored by lookups, and comments are dropped.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace igds {

// A comment line: its first non-blank character is `*` (CMS) or `⍝` (APL lamp).
bool is_comment_line(std::string_view line);

// The words of `line`: separated by blanks, tabs and commas, everything from a `⍝` on dropped,
// nothing for a comment line.
std::vector<std::string> split_words(std::string_view line);

// ASCII capitals (the words of the manual are ASCII; other characters are kept as typed).
std::string upper(std::string_view text);

}  // namespace igds
