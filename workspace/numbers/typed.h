// Numbers as people type them and as igds shows them back: APL\360's notation (`¯3.5`, `1E¯3`,
// `.5`; ¯ is the high minus, U+00AF) in the entries of the conversation and in the statements of
// END APL, one reader for both.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace igds {

// The signs a number may carry besides the high minus: none in an APL statement, where - and +
// are functions; - and + too in a typed entry (`-3.5`, `+2`, `2.5e-2`).
enum class NumberSigns { apl, typed };

// A number at the start of a text: [sign] digits [. digits] [E|e [sign] digits], with at least
// one digit before the exponent (`.5` and `2.` are numbers). An E not followed by an exponent is
// not part of the number. `length` is 0 when no number starts there.
struct ScannedNumber {
  std::size_t length = 0;  // code units taken
  // The nearest double: an infinity beyond the largest, a zero below the smallest, of the sign.
  double value = 0;
};
ScannedNumber scan_number(std::string_view utf8, NumberSigns signs);
ScannedNumber scan_number(std::u32string_view text, NumberSigns signs);

// A typed word that is one number and nothing else (NumberSigns::typed), or nullopt. Values
// beyond the largest double are infinities: callers refuse them with the point number. Inline:
// an optional returned from a call is put together in memory and read back at once, which
// stalls the processor on each of BUILD's hundreds of thousands of numbers.
inline std::optional<double> parse_typed_number(std::string_view word) {
  const ScannedNumber n = scan_number(word, NumberSigns::typed);
  if (n.length == 0 || n.length != word.size()) return std::nullopt;
  return n.value;
}

// A number as APL shows it: high minus for negatives, at most 10 significant digits, no trailing
// zeros, an exponent as in `1.5E¯7` when the value is very large or small.
std::string format_typed_number(double value);

}  // namespace igds
