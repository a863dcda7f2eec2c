// The ∇ line editor of APL\360 (User's Manual, chapter 5, "function definition" and "function
// editing"): lines are typed after a prompt [n]; [n] moves to line n (a fraction such as [2.5]
// inserts between lines), [n] text replaces or inserts line n, [⎕] lists the function, [⎕n]
// lists from line n, [n⎕] shows line n to be retyped, [n⎕m] edits line n from position m (below),
// [∆n] deletes line n, [0] the header; ∇ at the end of a line closes the definition (the lines
// then numbered 1, 2, ...), and so does ∇ at the start of a line, which is then read as typed at
// the six-blank prompt (`∇G` closes the function and opens G).
//
// [n⎕m] is APL\360's line editing: line n is shown as `[n] text`, and the next line is typed
// under it from position m (the first position of the shown line is 1): a / under a character
// deletes it, a digit d inserts d blanks before it, a letter inserts 5, 10, ... 130 (A, B, ...
// Z). The revised line is shown and the next line typed from its first inserted blank (or its
// end) is laid over it: what is typed replaces the blanks and characters it falls on, a blank
// typed leaves the character under it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace igds::apl {

class Editor {
 public:
  // Opens on a function's source: the header, then the lines (a new function has only its
  // header). The prompt is the line after the last.
  explicit Editor(const std::vector<std::string>& source);

  struct Step {
    std::vector<std::string> output;  // a listing, or DEFN ERROR for a bad editor command
    bool close = false;               // the line ended with ∇, or began with it
    bool reopen = false;              // it began with ∇ and more: the line, typed at the prompt
  };
  Step line(std::string_view typed);

  // The prompt for the next line: "[n] ", or blanks up to the position of [n⎕m] editing.
  std::string prompt() const;
  // The header and the lines in order (the function as it would be closed now).
  std::vector<std::string> source() const;
  const std::string& header() const { return header_; }

 private:
  using Number = std::int64_t;  // a line number times 10000: [2.5] is 25000
  static constexpr Number unit = 10000;

  void set_line(Number n, std::string text);
  std::vector<std::string> list(Number from, Number to) const;
  static std::string number_text(Number n);
  const std::string* text_of(Number n) const;
  Step start_editing(Number n, std::size_t position);
  Step marks(std::u32string_view typed);
  Step overlay(std::u32string_view typed);

  std::string header_;
  std::vector<std::pair<Number, std::string>> lines_;
  Number current_ = unit, step_ = unit;
  // [n⎕m]: the line being edited, as shown ("[n] text"), its prefix's length, and the column
  // (from 0) where the next line typed starts.
  enum class Mode { lines, marks, overlay } mode_ = Mode::lines;
  Number edited_ = 0;
  std::u32string shown_;
  std::size_t prefix_ = 0, column_ = 0;
};

}  // namespace igds::apl
