#include "workspace/kernels/data_error.h"

#include <algorithm>
#include <atomic>
#include <cmath>

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
