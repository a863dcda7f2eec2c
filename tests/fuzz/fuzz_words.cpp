// libFuzzer target of the line parser and the number reader (interp/words.h,
// workspace/numbers/typed.h): any line is split into words, each word read as an APL number and
// looked up as a command and as a choice of the projections; nothing may crash, and a number read
// is what its text says once written back and read again. Seeds: tests/fuzz/corpus/words.
//   scripts/fuzz 300 words
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

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
  for (const auto& word : split_words(line)) {
    if (word.empty()) std::abort();
    (void)find_command(word);
    (void)choose(projection_choices(), word);
    (void)upper(word);
    if (auto v = parse_typed_number(word); v && std::isfinite(*v)) {
      // What APL prints reads back within its ten digits.
      const auto again = parse_typed_number(format_typed_number(*v));
      if (!again || std::abs(*again - *v) > 1e-9 * std::max(1.0, std::abs(*v))) std::abort();
    }
  }
  return 0;
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(words)
