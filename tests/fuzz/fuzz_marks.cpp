// libFuzzer target of the readers of Marks's files (workspace/exchange/): the first byte says
// which; the rest is a fitting deck (NAME.CADADATA: read_deck, then fit_deck on what it accepts)
// or a paper tape (NAME.MPDPTAPE: read_tape, then tape_text). Whatever the bytes, a reader
// returns what it read or throws its own error; nothing read is half a thing. Seeds:
// tests/fuzz/corpus/marks.
//   scripts/fuzz 300 marks
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "workspace/exchange/marks_deck.h"
#include "workspace/exchange/mpdp_tape.h"
#include "workspace/kernels/data_error.h"

#include "tests/fuzz/fuzz.h"

namespace igds::fuzz {

int marks(const std::uint8_t* data, std::size_t size) {
  using namespace igds;
  using namespace igds::exchange;
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] % 2 == 0) {
    MarksDeck deck;
    try {
      deck = read_deck(bytes);
    } catch (const DeckError&) {
      return 0;
    }
    if (deck.keys.size() != std::size_t(deck.rows) * std::size_t(deck.columns)) std::abort();
    try {
      const MarksFit fit = fit_deck(deck);
      if (fit.patches.size() != std::size_t(deck.rows - 1) * std::size_t(deck.columns - 1) * 48)
        std::abort();
    } catch (const DataError&) {
      // A deck whose points the kernels refuse (coincident, not finite) is refused as data.
    }
    return 0;
  }
  try {
    const auto patches = read_tape(bytes);
    if (tape_text(patches).empty()) std::abort();
  } catch (const TapeError&) {
  }
  return 0;
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(marks)
