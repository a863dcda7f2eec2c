// APL numbers: reading them as the user types them, writing them as APL shows them.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace igds {

// `12`, `-3.5`, `¯3.5` (high minus U+00AF), `1E3`, `2.5E¯2`, `2.5e-2`, `-1.5E+03`. Anything
// else (including a trailing junk character or an empty word) gives nullopt. Values that
// overflow give an infinity: callers refuse non-finite values with the point number.
std::optional<double> parse_apl_number(std::string_view word);

// A number as APL prints it: high minus for negatives, at most 10 significant digits, no
// trailing zeros, an exponent as in `1.5E¯7` when the value is very large or small.
std::string format_apl_number(double value);

}  // namespace igds
