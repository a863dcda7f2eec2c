#include "workspace/exchange/marks_listing.h"

#include <cmath>
#include <cstring>

#include "workspace/numbers/fortran.h"

namespace igds::exchange {

std::string cada_listing(const MarksDeck& deck, const MarksFit& fit, std::size_t* overflow) {
  std::size_t stars = 0;
  std::string out;
  // Fw.d; a value that is not finite is asterisks too, like one that does not fit.
  auto field = [&](double value, int width, int decimals) {
    char text[16];
    if (!(std::isfinite(value) && fortran::put_f(text, value, width, decimals))) {
      std::memset(text, '*', std::size_t(width));
      ++stars;
    }
    out.append(text, std::size_t(width));
  };
  // Three numbers, the first widened by three blanks when it opens a group (F10.1, 2F7.1).
  auto vector = [&](Vec3 v, bool opens_group) {
    field(v.x, opens_group ? 10 : 7, 1);
    field(v.y, 7, 1);
    field(v.z, 7, 1);
  };
  const std::size_t n = deck.keys.size();
  const auto points = as_vec3(deck.points);
  const auto twists = as_vec3(fit.twists);
  for (std::size_t k = 0; k < n; ++k) {
    field(deck.keys[k], 4, 0);
    vector(points[k], false);
    vector(fit.tangents.along_curves[k], true);
    vector(fit.tangents.along_stringers[k], true);
    vector(twists[k], true);
    out += '\n';
  }
  out += '\n';
  const std::size_t patches = fit.patches.size() / 48;
  for (std::size_t p = 0; p < patches; ++p) {
    const double* m = fit.patches.data() + 48 * p;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 3; ++c) {
        for (int e = 0; e < 4; ++e) field(m[16 * c + 4 * r + e], c > 0 && e == 0 ? 10 : 7, 1);
      }
      out += '\n';
    }
    out += '\n';
  }
  if (overflow) *overflow = stars;
  return out;
}

}  // namespace igds::exchange
