// libFuzzer target of the line parser and the number reader (interp/words.h,
// workspace/numbers/typed.h): any line is split into words, each word read as an APL number and
// looked up as a command and as a choice of the projections; nothing may crash, the words' views
// are the words, a number of ASCII characters is strtod's double, and a number read is what its
// text says once written back and read again. Seeds: tests/fuzz/corpus/words.
//   scripts/fuzz 300 words
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "commands/command.h"
#include "commands/view.h"
#include "interp/words.h"
#include "workspace/numbers/typed.h"

#include "tests/fuzz/fuzz.h"

namespace igds::fuzz {

int words(const std::uint8_t* data, std::size_t size) {
  using namespace igds;
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  (void)is_comment_line(line);
  const std::vector<std::string> words = split_words(line);
  // The views are the same words, in the line itself.
  std::vector<std::string_view> views;
  split_words(line, views);
  if (views.size() != words.size()) std::abort();
  for (std::size_t k = 0; k < views.size(); ++k)
    if (views[k] != words[k] || views[k].data() < line.data() ||
        views[k].data() + views[k].size() > line.data() + line.size())
      std::abort();
  for (const auto& word : words) {
    if (word.empty()) std::abort();
    (void)find_command(word);
    (void)choose(projection_choices(), word);
    (void)upper(word);
    const auto v = parse_typed_number(word);
    // A number of ASCII digits, point, signs and exponent is strtod's double, bit for bit.
    if (v && word.find_first_not_of("0123456789.+-Ee") == std::string::npos) {
      const double c = std::strtod(word.c_str(), nullptr);
      if (std::memcmp(&c, &*v, sizeof c) != 0) std::abort();
    }
    if (v && std::isfinite(*v)) {
      // What APL prints reads back within its ten digits.
      const auto again = parse_typed_number(format_typed_number(*v));
      if (!again || std::abs(*again - *v) > 1e-9 * std::max(1.0, std::abs(*v))) std::abort();
    }
  }
  return 0;
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(words)
