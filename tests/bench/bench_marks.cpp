// Speed of Marks's tangents and twists (workspace/kernels/marks.h) on the 500 x 500 grid of the
// "grid" benchmark, against the interpolation of that grid (INTCU = INTST = 8).
#include <fmt/core.h>

#include <cmath>
#include <cstddef>
#include <utility>

#include "tests/bench/bench.h"
#include "workspace/kernels/coons.h"
#include "workspace/kernels/fit.h"
#include "workspace/kernels/marks.h"

namespace {

using igds::Array;

// The "grid" benchmark's surface (bench_kernels.cpp): NOCUR x NOSTR points, border tangents.
void wavy(int nocur, int nostr, Array& inppn, Array& inptg) {
  inppn = Array({std::size_t(nocur) * nostr, 3});
  inptg = Array({2 * std::size_t(nocur + nostr), 4});
  auto pts = igds::as_vec3(inppn);
  for (int i = 0; i < nocur; ++i)
    for (int j = 0; j < nostr; ++j)
      pts[i * nostr + j] = {j * 1.0, i * 1.5, 10 * std::sin(0.05 * j) * std::cos(0.03 * i)};
  double* t = inptg.data();
  for (int r = 0; r < 2 * (nocur + nostr); ++r) {
    bool along_curve = r < 2 * nocur;
    t[4 * r] = along_curve ? 1 : 0, t[4 * r + 1] = along_curve ? 0 : 1, t[4 * r + 2] = 0;
  }
}

}  // namespace

IGDS_BENCH("marks") {
  const int n = 500;
  Array inppn, inptg;
  wavy(n, n, inppn, inptg);
  const auto points = igds::as_vec3(std::as_const(inppn));
  Array border, twists;
  igds::GridTangents tangents;
  // AUTO at TANGENTS?: the border tangents; CHANGE TWISTS MARKS: the twists at every point.
  const double automatic =
      igds::bench::best_seconds(10, [&] { border = igds::marks_border_tangents(n, n, points); });
  const double twist =
      igds::bench::best_seconds(10, [&] { twists = igds::marks_twists(n, n, points); });
  // FIT: Marks's tangents at every point, then PATCHES from them with the twists.
  const double all =
      igds::bench::best_seconds(10, [&] { tangents = igds::marks_grid_tangents(n, n, points); });
  Array patches;
  const double build = igds::bench::best_seconds(10, [&] {
    igds::coons_patches(n, n, points, tangents, patches, igds::as_vec3(std::as_const(twists)));
  });
  // The interpolation of the same grid with INTCU = INTST = 8 (20.2 million points), recomputed
  // into the arrays of a previous run as in "grid": COONS then FIT called directly, since
  // interpolate() refuses grids above limits.h's max_grid_points.
  Array grid_patches, intpn;
  auto interpolation = [&] {
    igds::coons_patches(n, n, points, igds::grid_tangents(n, n, points, inptg), grid_patches);
    igds::fit(n, n, 8, 8, grid_patches, points, intpn);
  };
  interpolation();
  const double grid = igds::bench::best_seconds(5, interpolation);
  fmt::print("marks_auto_500x500_ms {:.3f}\n", automatic * 1e3);
  fmt::print("marks_twists_500x500_ms {:.2f}\n", twist * 1e3);
  fmt::print("marks_tangents_500x500_ms {:.2f}\n", all * 1e3);
  fmt::print("marks_patches_500x500_ms {:.2f}\n", build * 1e3);
  fmt::print("grid_500x500_int8_ms {:.1f}\n", grid * 1e3);
  fmt::print("marks_over_grid {:.3f}\n", (automatic + twist) / grid);
}
