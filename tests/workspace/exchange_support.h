// Shared by the exchange tests: the small surface of the golden files, larger ones, and an
// independent evaluation of Bézier spans. Golden files are compared by tests/support/golden.h.
#pragma once

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/kernels/helpers.h"
#include "tests/support/golden.h"
#include "tests/support/process.h"
#include "workspace/kernels/surface.h"
#include "workspace/kernels/vec3.h"

namespace igds::test::exchange {

using test::Random;  // tests/kernels/helpers.h

// A NOCUR x NOSTR surface with border tangents: a bent, twisted sheet with uneven chords (so
// that it is C0 only across its patch borders), in the INPTG row order of workspace/state.h.
struct TestSurface {
  Array inppn, inptg;
  SurfaceInput input;
  Surface surface;
};

inline TestSurface test_surface(int nocur, int nostr, int intcu, int intst) {
  TestSurface t;
  t.inppn = Array({std::size_t(nocur) * std::size_t(nostr), 3});
  t.inptg = Array({2 * std::size_t(nocur + nostr), 4});
  for (int i = 0; i < nocur; ++i) {
    for (int j = 0; j < nostr; ++j) {
      double* p = t.inppn.data() + 3 * (i * nostr + j);
      p[0] = 10.0 * j + 0.7 * j * j + 1.5 * i * i;
      p[1] = 8.0 * i + 0.3 * j * j;
      p[2] = 3 * std::sin(0.7 * i + 0.4 * j) + 0.1 * i * j;
    }
  }
  for (int r = 0; r < 2 * (nocur + nostr); ++r) {
    double* tg = t.inptg.data() + 4 * r;
    const bool along_curve = r < 2 * nocur;
    tg[0] = along_curve ? 1 : 0.1;
    tg[1] = along_curve ? 0.1 : 1;
    tg[2] = 0.2;
  }
  t.input = {nocur, nostr, intcu, intst, &t.inppn, &t.inptg};
  t.surface = interpolate(t.input);
  return t;
}

// The surface of the golden files: 5 curves of 4 points, 2 curves and 2 stringers between.
inline TestSurface golden_surface() {
  return test_surface(5, 4, 2, 2);
}

inline Vec3 bezier3(const Vec3 c[4], double t) {
  const double s = 1 - t;
  return (s * s * s) * c[0] + (3 * s * s * t) * c[1] + (3 * s * t * t) * c[2] + (t * t * t) * c[3];
}

// The largest absolute coordinate: the scale of "relative" errors.
inline double largest_coordinate(const Array& a) {
  double m = 0;
  for (double v : a.ravel) m = std::max(m, std::abs(v));
  return m;
}

using igds::test::check_golden;

}  // namespace igds::test::exchange
