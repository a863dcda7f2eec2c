#include "workspace/kernels/data_error.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "workspace/kernels/array.h"
#include "workspace/kernels/parallel.h"

namespace igds {

const char* DataError::what() const noexcept {
  try {
    switch (problem) {
      case Problem::point_not_finite:
        text_ = fmt::format("point {} is not finite", number);
        break;
      case Problem::tangent_not_finite:
        text_ = fmt::format("the tangent at point {} is not finite", number);
        break;
      case Problem::patch_not_finite:
        text_ = fmt::format("patch {} is not finite", number);
        break;
      case Problem::twist_not_finite:
        text_ = fmt::format("the twist at point {} is not finite", number);
        break;
      case Problem::shape:
        text_ = fmt::format("{} has shape {}, not {}", variable, fmt::join(shape, " "),
                            fmt::join(expected, " "));
        break;
      case Problem::missing:
        text_ = fmt::format("{} is missing", variable);
        break;
      case Problem::grid_too_small:
        text_ = "the grid is too small";
        break;
      case Problem::negative_density:
        text_ = "INTCU or INTST is negative";
        break;
      case Problem::too_many_points:
        text_ = fmt::format("{:.0f} points, more than {:.0f}", count, limit);
        break;
      case Problem::projection_parameters:
        text_ = "projection parameters out of range";
        break;
      case Problem::behind_eye:
        text_ = "a point is behind the eye";
        break;
      case Problem::view_at_centre:
        text_ = "the view point is the centre";
        break;
      case Problem::view_inside_box:
        text_ = "the view point is inside the bounding box";
        break;
      case Problem::grid_point_not_finite:
        text_ = fmt::format("INTPN row {} column {} is not finite", number, column);
        break;
      case Problem::image_not_finite:
        text_ =
            fmt::format("the image of {} {} (column {}) is not finite", variable, number, column);
        break;
    }
  } catch (...) {
    return "data error";
  }
  return text_.c_str();
}

namespace {

// first_not_finite on [first, last): a block at a time, x * 0 is 0 for every finite x and NaN for
// the rest, and the sums of four independent lanes keep the loop at the speed of memory; a block
// whose sum is not 0 is searched number by number.
std::size_t first_not_finite_in(const double* v, std::size_t first, std::size_t last) {
  constexpr std::size_t block = 1024;
  for (std::size_t from = first; from < last; from += block) {
    const std::size_t to = std::min(last, from + block);
    double lane[4] = {0, 0, 0, 0};
    std::size_t k = from;
    for (; k + 4 <= to; k += 4)
      for (int j = 0; j < 4; ++j) lane[j] += v[k + j] * 0.0;
    for (; k < to; ++k) lane[0] += v[k] * 0.0;
    if (lane[0] + lane[1] + lane[2] + lane[3] == 0) continue;
    for (k = from; k < to; ++k)
      if (!std::isfinite(v[k])) return k;
  }
  return last;
}

}  // namespace

std::size_t first_not_finite(const double* v, std::size_t n) {
  // Large arrays (INTPN, an image) on the cores the kernels made them with.
  std::atomic<std::size_t> found{n};
  parallel_for(n, threads_for(n), [&](std::size_t first, std::size_t last) {
    const std::size_t k = first_not_finite_in(v, first, last);
    if (k < last) keep_least(found, k);
  });
  return found.load();
}

FinitePoints finite_points(const double* xy, std::size_t n) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const unsigned parts = threads_for(2 * n);
  std::atomic<std::size_t> found{2 * n};
  std::vector<std::array<double, 4>> boxes(parts, {inf, inf, -inf, -inf});
  parallel_for(parts, parts, [&](std::size_t first_part, std::size_t last_part) {
    for (std::size_t part = first_part; part < last_part; ++part) {
      const std::size_t first = n * part / parts, last = n * (part + 1) / parts;
      // Here, not in boxes: the threads' boxes share a cache line. Two chains, the even points
      // and the odd, so that each comparison waits on the one two points before.
      double low[4] = {inf, inf, inf, inf}, high[4] = {-inf, -inf, -inf, -inf};
      auto take = [&](int c, const double* p) {
        low[c] = std::min(low[c], p[0]), low[c + 1] = std::min(low[c + 1], p[1]);
        high[c] = std::max(high[c], p[0]), high[c + 1] = std::max(high[c + 1], p[1]);
      };
      constexpr std::size_t block = 512;
      for (std::size_t from = first; from < last; from += block) {
        const std::size_t to = std::min(last, from + block);
        double seen[4] = {0, 0, 0, 0};
        std::size_t k = from;
        for (; k + 2 <= to; k += 2) {
          const double* p = xy + 2 * k;
          for (int j = 0; j < 4; ++j) seen[j] += p[j] * 0.0;
          take(0, p), take(2, p + 2);
        }
        if (k < to) seen[0] += xy[2 * k] * 0.0 + xy[2 * k + 1] * 0.0, take(0, xy + 2 * k);
        if (seen[0] + seen[1] + seen[2] + seen[3] != 0) {
          keep_least(found, 2 * from + first_not_finite_in(xy + 2 * from, 0, 2 * (to - from)));
          break;
        }
      }
      boxes[part] = {std::min(low[0], low[2]), std::min(low[1], low[3]), std::max(high[0], high[2]),
                     std::max(high[1], high[3])};
    }
  });
  FinitePoints out{found.load(), {inf, inf, -inf, -inf}};
  for (const auto& b : boxes)
    out.box = {std::min(out.box[0], b[0]), std::min(out.box[1], b[1]), std::max(out.box[2], b[2]),
               std::max(out.box[3], b[3])};
  return out;
}

void require_shape(const char* variable, const Array* a, std::vector<std::size_t> expected) {
  if (a == nullptr) {
    DataError e(DataError::Problem::missing);
    e.variable = variable;
    throw e;
  }
  if (a->shape != expected || a->size() != Array::count(expected)) {
    DataError e(DataError::Problem::shape);
    e.variable = variable;
    e.shape = a->shape;
    e.expected = std::move(expected);
    throw e;
  }
}

}  // namespace igds
