// The words of a line as IGDS reads them (docs/interp.md, "The dialogue"): blanks and commas
// separate words, case is ignored by lookups, and comments are dropped.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace igds {

// A comment line: its first non-blank character is `*` (CMS) or `⍝` (APL lamp). The manual's
// comments are IGDS's: while END APL reads its lines no line is one (`*1` is a statement, ⍞
// takes any line, the ∇ editor keeps a function's ⍝ lines), so the readers, which drop comment
// lines, give them all.
bool is_comment_line(std::string_view line);

// While one exists, lines are read for END APL (`apl`) or again for IGDS (a command run from
// APL, COMDIS ...); the one before is back when it goes.
class ReadingFor {
 public:
  explicit ReadingFor(bool apl);
  ~ReadingFor();
  ReadingFor(const ReadingFor&) = delete;
  ReadingFor& operator=(const ReadingFor&) = delete;

 private:
  bool was_;
};

// The words of `line`: separated by blanks, tabs and commas, everything from a `⍝` on dropped,
// nothing for a comment line.
std::vector<std::string> split_words(std::string_view line);
// The same words as views of `line`, into `words` (its room kept from line to line): no word is
// copied.
void split_words(std::string_view line, std::vector<std::string_view>& words);

// ASCII capitals (the words of the manual are ASCII; other characters are kept as typed).
std::string upper(std::string_view text);

}  // namespace igds
