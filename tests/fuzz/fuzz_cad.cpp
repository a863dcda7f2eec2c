// libFuzzer target of the CAD surface readers (workspace/exchange/cad_read.h): the first byte says
// which (even IGES, odd STEP), the rest is the file. Whatever the bytes, the reader returns a
// surface that passed its checks or throws CadReadError with a reason, in time and memory
// proportional to the input; a surface it returns evaluates anywhere in its range. Seeds:
// tests/fuzz/corpus/cad (IGES and STEP files igds and OpenCASCADE wrote).
//   scripts/fuzz 300 cad
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "tests/fuzz/fuzz.h"
#include "workspace/exchange/cad_read.h"

namespace igds::fuzz {

int cad(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  CadSurface s;
  try {
    s = data[0] % 2 == 0 ? read_iges_surface(text) : read_step_surface(text);
  } catch (const CadReadError& e) {
    if (std::string_view(e.what()).empty()) std::abort();
    return 0;
  }
  if (s.controls.size() != s.count_u * s.count_v ||
      s.knots_u.size() != s.count_u + std::size_t(s.degree_u) + 1 ||
      s.knots_v.size() != s.count_v + std::size_t(s.degree_v) + 1 || !(s.u0 < s.u1) ||
      !(s.v0 < s.v1))
    std::abort();
  for (double t : {0.0, 0.25, 0.5, 1.0}) {
    evaluate(s, s.u0 + t * (s.u1 - s.u0), s.v0 + t * (s.v1 - s.v0));
    evaluate(s, s.u0 - 1, s.v1 + 1);  // outside: clamped
  }
  return 0;
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(cad)
