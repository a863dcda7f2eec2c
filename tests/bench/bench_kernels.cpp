// Speed of the surface kernels: interpolation of a large grid against the machine's memcpy rate,
// one long spline, the CHANGE GRID recompute, and the hidden lines of a large grid.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "tests/bench/bench.h"
#include "tests/bench/inputs.h"
#include "workspace/kernels/coons.h"
#include "workspace/kernels/curvature.h"
#include "workspace/kernels/hidden.h"
#include "workspace/kernels/project.h"
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
  (void)igds::interpolate_into(si, surface);
  const std::size_t points = surface.intpn.size() / 3;
  const double seconds =
      igds::bench::best_seconds(5, [&] { (void)igds::interpolate_into(si, surface); });
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
  // The tangents of every curve and stringer of the largest grid igds takes: 500 x 500 lines of
  // 500 points, the curves' and the stringers' on a thread each.
  const Input in = wavy(500, 500);
  const double grid = igds::bench::best_seconds(
      5, [&] { (void)igds::grid_tangents(in.nocur, in.nostr, igds::as_vec3(in.inppn), in.inptg); });
  fmt::print("grid_tangents_500x500_ms {:.2f}\n", grid * 1e3);
}

IGDS_BENCH("recompute") {
  const Input in = wavy(100, 100);
  const igds::Surface s = igds::interpolate({in.nocur, in.nostr, 1, 1, &in.inppn, &in.inptg});
  const igds::SurfaceInput si{in.nocur, in.nostr, 10, 10, &in.inppn, &in.inptg};
  double seconds = igds::bench::best_seconds(10, [&] { igds::refit(si, s.patches); });
  fmt::print("recompute_100x100_int10_ms {:.2f}\n", seconds * 1e3);
}

IGDS_BENCH("hidden") {
  // DISPLAY HIDDEN's own work on a surface of 1 M and of 4 M interpolated points: how near each
  // point is, then the visible pieces on the raster the picture uses (3072 cells across), in an
  // assonometric view where the wave's crests hide part of its troughs. The growth from 1 M to
  // 4 M points says the cost is linear in the segments (4 when it is).
  double at_1m = 0;
  for (const auto& [nocur, points_key] : {std::pair{251, "1m"}, std::pair{500, "4m"}}) {
    const Input in = wavy(nocur, nocur);
    const igds::Surface s = igds::interpolate({in.nocur, in.nostr, 3, 3, &in.inppn, &in.inptg});
    const std::size_t planes = s.intpn.shape[0], rows = s.intpn.shape[1];
    const auto points = igds::as_vec3(s.intpn);
    const igds::View view{igds::Projection::assonometric, {110, 130, 120}};
    const igds::Vec3 centre = igds::bounding_box_centre(igds::as_vec3(in.inppn));
    std::vector<double> xy(2 * points.size()), near(points.size());
    igds::project(view, centre, points, igds::MutablePoint2View(xy.data(), points.size()));
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (std::size_t k = 0; k < points.size(); ++k) {
      x0 = std::min(x0, xy[2 * k]), x1 = std::max(x1, xy[2 * k]);
      y0 = std::min(y0, xy[2 * k + 1]), y1 = std::max(y1, xy[2 * k + 1]);
    }
    const igds::Raster raster{x0, y0, x1, y1, std::max(x1 - x0, y1 - y0) / 3072};
    std::size_t pieces = 0;
    const double seconds = igds::bench::best_seconds(3, [&] {
      igds::nearness(view, centre, points, near);
      pieces = igds::visible_pieces({planes, rows, xy.data(), near.data()}, raster).size();
    });
    fmt::print("hidden_lines_{}_points {}\n", points_key, points.size());
    fmt::print("hidden_lines_{}_pieces {}\n", points_key, pieces);
    fmt::print("hidden_lines_{}_ms {:.1f}\n", points_key, seconds * 1e3);
    if (at_1m == 0)
      at_1m = seconds / double(points.size());
    else
      fmt::print("hidden_lines_4m_over_1m_per_point {:.2f}\n",
                 seconds / double(points.size()) / at_1m);
  }
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
