// Speed of the surface kernels: interpolation of a large grid against the machine's memcpy rate,
// one long spline, and the CHANGE GRID recompute.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "tests/bench/bench.h"
#include "tests/bench/inputs.h"
#include "workspace/kernels/curvature.h"
#include "workspace/kernels/spline.h"
#include "workspace/kernels/surface.h"
#include "workspace/kernels/vec3.h"

namespace {

using igds::bench::Input;
using igds::bench::wavy;

using igds::Array;
using igds::Vec3;

}  // namespace

IGDS_BENCH("grid") {
  // The largest grid igds takes: 500 x 500 inputs, INTCU = INTST = 3, 1999 x 1999 points.
  const Input in = wavy(500, 500);
  const igds::SurfaceInput si{in.nocur, in.nostr, 3, 3, &in.inppn, &in.inptg};
  // Recomputed into the arrays of the previous run (interpolate_into), as a recompute of a
  // surface of the same size does: the memory is already mapped.
  igds::Surface surface;
  igds::interpolate_into(si, surface);
  const std::size_t points = surface.intpn.size() / 3;
  const double seconds = igds::bench::best_seconds(5, [&] { igds::interpolate_into(si, surface); });
  fmt::print("grid_500x500_int3_points {}\n", points);
  fmt::print("grid_500x500_int3_ms {:.1f}\n", seconds * 1e3);
  fmt::print("grid_500x500_int3_mpts {:.1f}\n", points / seconds / 1e6);
  // Into new arrays (interpolate): the system must first map and clear 96 MB of fresh pages.
  double fresh = 1e300;
  for (int run = 0; run < 5; ++run) {
    auto t0 = std::chrono::steady_clock::now();
    igds::Surface s = igds::interpolate(si);
    fresh = std::min(fresh,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }  // each surface is freed outside the timed part
  fmt::print("grid_500x500_int3_new_arrays_ms {:.1f}\n", fresh * 1e3);
  fmt::print("grid_500x500_int3_new_arrays_mpts {:.1f}\n", points / fresh / 1e6);
  // The same volume copied by memcpy between two buffers already in memory.
  std::vector<double> from(points * 3, 1.0), to(points * 3, 0.0);
  const double copy = igds::bench::best_seconds(
      5, [&] { std::memcpy(to.data(), from.data(), from.size() * sizeof(double)); });
  fmt::print("memcpy_mpts {:.1f}\n", points / copy / 1e6);
  fmt::print("grid_over_memcpy {:.2f}\n", copy / seconds);
}

IGDS_BENCH("spline") {
  const std::size_t n = 1000000;
  igds::Array pts({n, 3});
  std::vector<Vec3> tangents(n);
  for (std::size_t k = 0; k < n; ++k)
    igds::as_vec3(pts)[k] = Vec3{double(k), std::sin(0.001 * k), 0.5 * (k % 7)};
  igds::SplineScratch scratch;
  double seconds = igds::bench::best_seconds(5, [&] {
    igds::spline_tangents(igds::as_vec3(std::as_const(pts)), {1, 0, 0}, {1, 0, 0}, tangents,
                          scratch);
  });
  fmt::print("spline_1e6_ms {:.2f}\n", seconds * 1e3);
}

IGDS_BENCH("recompute") {
  const Input in = wavy(100, 100);
  const igds::Surface s = igds::interpolate({in.nocur, in.nostr, 1, 1, &in.inppn, &in.inptg});
  const igds::SurfaceInput si{in.nocur, in.nostr, 10, 10, &in.inppn, &in.inptg};
  double seconds = igds::bench::best_seconds(10, [&] { igds::refit(si, s.patches); });
  fmt::print("recompute_100x100_int10_ms {:.2f}\n", seconds * 1e3);
}

IGDS_BENCH("curvature") {
  // DISPLAY COMBS's curvature of about a million points (991 x 991), against FIT of the same grid.
  const Input in = wavy(100, 100);
  const igds::SurfaceInput si{in.nocur, in.nostr, 9, 9, &in.inppn, &in.inptg};
  const igds::Surface s = igds::interpolate(si);
  double seconds = igds::bench::best_seconds(5, [&] { igds::grid_curvature(si, s.patches); });
  double fit = igds::bench::best_seconds(5, [&] { igds::refit(si, s.patches); });
  fmt::print("curvature_100x100_int9_ms {:.2f}\n", seconds * 1e3);
  fmt::print("curvature_over_fit {:.2f}\n", seconds / fit);
}
