// The ∇ line editor of APL\360 (User's Manual, chapter 5, "function definition" and "function
// editing"): lines are typed after a prompt [n]; [n] moves to line n (a fraction such as [2.5]
// inserts between lines), [n] text replaces or inserts line n, [⎕] lists the function, [⎕n]
// lists from line n, [n⎕] shows line n to be retyped, [∆n] deletes line n, [0] the header, and
// ∇ at the end of a line closes the definition, the lines then numbered 1, 2, ...
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
    bool close = false;               // the line ended with ∇
  };
  Step line(std::string_view typed);

  // The prompt for the next line: "[n] ".
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

  std::string header_;
  std::vector<std::pair<Number, std::string>> lines_;
  Number current_ = unit, step_ = unit;
};

}  // namespace igds::apl
