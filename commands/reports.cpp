#include "commands/reports.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace igds {

namespace {

std::string shape_text(const std::vector<std::size_t>& shape) {
  return shape.empty() ? std::string("EMPTY") : fmt::format("{}", fmt::join(shape, " "));
}

}  // namespace

Report worded(const DataError& e) {
  using P = DataError::Problem;
  switch (e.problem) {
    case P::point_not_finite:
      return Report(reports::incorrect_entry,
                    fmt::format("POINT {} IS NOT A FINITE NUMBER", e.number));
    case P::tangent_not_finite:
      return Report(reports::incorrect_entry,
                    fmt::format("TANGENT AT POINT {} IS NOT A FINITE NUMBER", e.number));
    case P::twist_not_finite:
      return Report(reports::incorrect_entry,
                    fmt::format("TWIST AT POINT {} IS NOT A FINITE NUMBER", e.number));
    case P::patch_not_finite:
      return Report(reports::incorrect_entry,
                    fmt::format("PATCH {} IS NOT A FINITE NUMBER", e.number));
    case P::shape:
      return Report(reports::incorrect_entry,
                    fmt::format("{} HAS SHAPE {}, NOT {}", e.variable, shape_text(e.shape),
                                shape_text(e.expected)));
    case P::missing:
      return Report(reports::incorrect_entry, fmt::format("{} NOT FOUND", e.variable));
    case P::grid_too_small:
      return Report(reports::incorrect_parameter,
                    "NOCUR AND NOSTR MUST BE AT LEAST 1, AND THE GRID HAVE TWO POINTS");
    case P::negative_density:
      return Report(reports::incorrect_parameter, "INTCU AND INTST MUST NOT BE NEGATIVE");
    case P::too_many_points:
      return Report(
          reports::incorrect_entry,
          fmt::format("THE GRID WOULD HAVE {:.0f} POINTS, AT MOST {:.0f}", e.count, e.limit));
    case P::projection_parameters:
      return Report(reports::incorrect_parameter);
    case P::behind_eye:
      return Report(reports::incorrect_parameter, "A POINT IS BEHIND THE EYE");
    case P::view_at_centre:
      return Report(reports::incorrect_parameter, "THE VIEW POINT IS THE CENTRE OF THE SURFACE");
    case P::view_inside_box:
      return Report(reports::incorrect_parameter, "THE VIEW POINT IS INSIDE THE SURFACE'S BOX");
    case P::grid_point_not_finite:
      return Report(
          reports::incorrect_entry,
          fmt::format("INTPN ROW {} COLUMN {} IS NOT A FINITE NUMBER", e.number, e.column));
    case P::image_not_finite: {
      std::string what;
      if (e.variable == "INPPN")
        what = fmt::format("POINT {}", e.number);
      else if (e.variable == "INPTG")
        what = fmt::format("THE TANGENT AT POINT {}", e.number);
      else if (e.variable == "INTPN")
        what = fmt::format("INTPN ROW {} COLUMN {}", e.number, e.column);
      else
        what = fmt::format("ITEM {} OF THE PICTURE", e.number);
      return Report(reports::incorrect_parameter,
                    fmt::format("THE IMAGE OF {} IS NOT A FINITE NUMBER", what));
    }
  }
  return Report(reports::incorrect_entry);
}

Report worded(const DataError& e, std::string_view kept) {
  return Report(fmt::format("{}; {}", worded(e).line(), kept));
}

}  // namespace igds
