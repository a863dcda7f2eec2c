#include "workspace/kernels/data_error.h"

#include "workspace/kernels/array.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

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
    }
  } catch (...) {
    return "data error";
  }
  return text_.c_str();
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
