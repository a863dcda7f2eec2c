#include "commands/view.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "commands/command.h"
#include "commands/entries.h"
#include "workspace/apl.h"
#include "workspace/error.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/project.h"

namespace igds {

namespace {

std::optional<std::vector<double>> finite_numbers(std::span<const std::string> words) {
  std::vector<double> values;
  for (const auto& w : words) {
    auto v = parse_apl_number(w);
    if (!v || !std::isfinite(*v)) return std::nullopt;
    values.push_back(*v);
  }
  return values;
}

Description describe(int what, const View& view) {
  return {what, view.projection, view.parameters};
}

// The view point of a conic projection must lie outside what is looked at.
void check_view_point(const View& view, Vec3View points) {
  if (view.projection != Projection::conic) return;
  Vec3 v{view.parameters[0], view.parameters[1], view.parameters[2]};
  if (inside_bounding_box(points, v)) throw Report(reports::incorrect_parameter);
}

Array projected(Vec3View points, std::vector<std::size_t> shape, const View& view, Vec3 centre) {
  Array out(std::move(shape));
  try {
    project(view, centre, points, as_point2(out));
  } catch (const DataError&) {
    throw Report(reports::incorrect_parameter);
  }
  return out;
}

}  // namespace

std::optional<Projection> projection_named(std::string_view word) {
  static constexpr Projection codes[] = {Projection::conic, Projection::isometric,
                                         Projection::assonometric, Projection::orthogonal,
                                         Projection::assonometric};
  int i = lookup_prefix(projection_words(), word);
  if (i < 0) return std::nullopt;
  return codes[i];
}

std::optional<View> parse_view(Projection projection, std::span<const std::string> words) {
  View view{projection, {}};
  if (projection == Projection::orthogonal) {
    static constexpr std::string_view planes[] = {"XY", "XZ", "YZ"};  // codes 1 2 3
    // The plane is always both letters: X alone would be ambiguous.
    if (words.size() != 1 || words[0].size() != 2) return std::nullopt;
    int i = lookup_prefix(planes, words[0]);
    if (i < 0) return std::nullopt;
    view.parameters[0] = i + 1;
    return view;
  }
  auto values = finite_numbers(words);
  if (!values) return std::nullopt;
  switch (projection) {
    case Projection::conic:
      if (values->size() != 3) return std::nullopt;
      break;
    case Projection::isometric:
      if (values->size() != 2 || !parse_integer(words[0], 1, 3) ||
          !isom_parameters_valid((*values)[0], (*values)[1]))
        return std::nullopt;
      break;
    case Projection::assonometric:
      if (values->size() != 3 ||
          !asson_parameters_valid({(*values)[0], (*values)[1], (*values)[2]}))
        return std::nullopt;
      break;
    case Projection::orthogonal:
      break;
  }
  std::copy(values->begin(), values->end(), view.parameters.begin());
  return view;
}

Image input_image(const Workspace& ws, const View& view) {
  auto points = as_vec3(ws.inppn);
  check_view_point(view, points);
  const Vec3 centre = bounding_box_centre(points);
  Image image;
  image.desim = describe(0, view);
  image.points =
      projected(points, {static_cast<std::size_t>(ws.nocur), static_cast<std::size_t>(ws.nostr), 2},
                view, centre);

  // The diagonal of the bounding box sets the step of the numerical derivative.
  Vec3 low = points.empty() ? Vec3{} : points[0], high = low;
  for (Vec3 p : points) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  const double size = std::max(norm(high - low), 1e-9);

  std::vector<double> arrows;
  const std::size_t rows = ws.inptg.shape.empty() ? 0 : ws.inptg.shape[0];
  for (std::size_t r = 0; r < rows; ++r) {
    const double* row = ws.inptg.data() + r * 4;
    const Vec3 t{row[0], row[1], row[2]};
    const double length = norm(t);
    const auto k = static_cast<std::size_t>(row[3]);
    if (length == 0 || k < 1 || k > points.size()) continue;
    // The projection's derivative along T: (proj(P + hT) - proj(P)) / h, with h|T| small
    // against the surface, so that CONIC arrows follow the perspective at their base.
    const double h = 1e-6 * size / length;
    const Vec3 base = points[k - 1], tip = base + h * t;
    const double ends[6] = {base.x, base.y, base.z, tip.x, tip.y, tip.z};
    double projected[4];
    try {
      project(view, centre, Vec3View(ends, 2), MutablePoint2View(projected, 2));
    } catch (const DataError&) {
      throw Report(reports::incorrect_parameter);
    }
    arrows.insert(arrows.end(), {projected[0], projected[1], (projected[2] - projected[0]) / h,
                                 (projected[3] - projected[1]) / h});
  }
  if (!arrows.empty()) {
    image.arrows.shape = {arrows.size() / 4, 4};
    image.arrows.ravel = std::move(arrows);
  }
  return image;
}

Image surface_image(const Workspace& ws, const View& view) {
  auto points = as_vec3(ws.intpn);
  check_view_point(view, points);
  Image image;
  image.desim = describe(1, view);
  image.points = projected(points, {ws.intpn.shape[0], ws.intpn.shape[1], 2}, view,
                           bounding_box_centre(as_vec3(ws.inppn)));
  return image;
}

}  // namespace igds
