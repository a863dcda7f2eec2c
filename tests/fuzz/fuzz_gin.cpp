// libFuzzer target of the GIN report decoder and reader (devices/gin.h): any bytes, at both
// address widths; nothing may crash, a report takes 5 to 7 bytes, its position lies on the
// screen, and the same bytes decode the same way with what follows them changed; the reader, fed
// the bytes in pieces cut where the first byte says, finds the same mark and report as fed them
// whole. Seeds: tests/fuzz/corpus/gin.
//   scripts/fuzz 60 gin
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "devices/gin.h"

#include "tests/fuzz/fuzz.h"

namespace igds::fuzz {

int gin(const std::uint8_t* data, std::size_t size) {
  using namespace igds;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (const int bits : {10, 12}) {
    const auto r = decode_gin(bytes, bits);
    if (!r) continue;
    const int limit = bits == 12 ? 4096 : 1024;
    if (r->used < 5 || r->used > 7 || r->used > size) std::abort();
    if (r->x < 0 || r->y < 0 || r->x >= limit || r->y >= limit) std::abort();
    if (static_cast<unsigned char>(r->key) > 0x7F) std::abort();
    // The report alone decodes to the same report.
    const auto again = decode_gin(bytes.substr(0, r->used), bits);
    if (!again || again->x != r->x || again->y != r->y || again->used != r->used) std::abort();
  }
  if (size > 1) {
    const std::size_t cut = 1 + data[0] % (size - 1);
    GinReader whole(100, 200, 10), pieces(100, 200, 10);
    whole.feed(bytes.substr(1));
    pieces.feed(bytes.substr(1, cut - 1));
    pieces.feed(bytes.substr(cut));
    whole.settle();
    pieces.settle();
    if (whole.marked() != pieces.marked() || whole.ahead() != pieces.ahead() ||
        whole.done() != pieces.done() || whole.rest() != pieces.rest())
      std::abort();
    if (whole.ahead().size() + whole.rest().size() > size) std::abort();
  }
  return 0;
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(gin)
