// libFuzzer target of the DUCT reader (workspace/exchange/duct.h): whatever the bytes, read_duct
// returns a picture or throws DuctError, in time and memory proportional to the input; what it
// returns draws, writes and reads back; its drawing, in space and projected, writes and reads
// back, and written straight from the drawing (as EXPORT DUCT writes) is the same text. Seeds:
// tests/fuzz/corpus/duct (the golden and the hand-written pictures).
//   scripts/fuzz 300 duct
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "workspace/drawing/project.h"
#include "workspace/exchange/duct.h"
#include "workspace/kernels/data_error.h"
#include "workspace/text_out.h"

#include "tests/fuzz/fuzz.h"

namespace igds::fuzz {

int duct(const std::uint8_t* data, std::size_t size) {
  using namespace igds;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  DuctPicture picture;
  try {
    picture = read_duct(text);
  } catch (const DuctError& e) {
    if (e.line == 0 || e.reason().empty()) std::abort();
    return 0;
  }
  // Anything escaping from here is a finding: libFuzzer reports the uncaught exception.
  const Drawing3 drawing = duct_drawing(picture);
  const DuctPicture again = read_duct(write_duct(picture));
  if (again.instructions != picture.instructions || again.counters != picture.counters ||
      again.texts.size() != picture.texts.size() || again.pixel_count() != picture.pixel_count())
    std::abort();
  const std::string kept = write_duct(duct_picture(drawing, {"FUZZ", "", "AGAIN"}));
  read_duct(kept);
  StringOut streamed;
  write_duct(drawing, {"FUZZ", "", "AGAIN"}, {}, streamed);
  if (streamed.take_text() != kept) std::abort();
  try {
    const Drawing2 plane = project(drawing, {Projection::assonometric, {110, 130, 120}},
                                   bounding_box(drawing).centre());
    const std::string flat =
        write_duct(duct_picture(plane, {"FUZZ", "", ""}, Projection::assonometric));
    read_duct(flat);
    StringOut out;
    write_duct(plane, {"FUZZ", "", ""}, Projection::assonometric, out);
    if (out.take_text() != flat) std::abort();
  } catch (const DataError& e) {
    // Coordinates so large that their projection overflows are refused, nothing else.
    if (e.problem != DataError::Problem::point_not_finite) std::abort();
  }
  return 0;
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(duct)
