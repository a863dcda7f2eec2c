#include "commands/view.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/reports.h"
#include "workspace/apl.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/project.h"

namespace igds {

namespace {

constexpr Choice projections[] = {
    {"CONIC", static_cast<int>(Projection::conic), "x y z", "perspective from a view point"},
    {"ISOMETRIC", static_cast<int>(Projection::isometric), "axis angle",
     "an axis drawn obliquely at an angle"},
    {"ASSONOMETRIC", static_cast<int>(Projection::assonometric), "a b c",
     "a true axonometric view, three angles"},
    {"ORTHOGONAL", static_cast<int>(Projection::orthogonal), "plane", "onto XY, YZ or XZ"},
    {"AXONOMETRIC", static_cast<int>(Projection::assonometric), "a b c",
     "the same as ASSONOMETRIC"},
};

constexpr Choice planes[] = {
    {"XY", static_cast<int>(Plane::xy)},
    {"YZ", static_cast<int>(Plane::yz)},
    {"XZ", static_cast<int>(Plane::xz)},
};

const Prompt conic_prompt{"VIEW POINT X Y Z?",
                          "The eye's position x y z, outside the surface; the picture looks\n"
                          "at the centre of the input points."};
const Prompt isometric_prompt{"AXIS AND ANGLE?",
                              "The axis to drop (1 x, 2 y, 3 z) and the angle of its\n"
                              "projection, 0 to 90 degrees."};
const Prompt assonometric_prompt{"THREE ANGLES?",
                                 "The angles between the projected x-y, y-z and z-x axes, each\n"
                                 "between 90 and 180, sum 360 (try 110 130 120)."};
const Prompt orthogonal_prompt{"PLANE XY, YZ OR XZ?", "The plane to project on: XY, YZ or XZ.",
                               planes};

std::vector<double> numbers(std::span<const std::string> words) {
  std::vector<double> values;
  for (const auto& w : words) {
    auto v = parse_apl_number(w);
    if (!v || !std::isfinite(*v)) throw ParameterError(fmt::format("{} IS NOT A NUMBER", w));
    values.push_back(*v);
  }
  return values;
}

// The view point of a conic projection must lie outside what is looked at.
void check_view_point(const View& view, Vec3View points) {
  if (view.projection != Projection::conic) return;
  Vec3 v{view.parameters[0], view.parameters[1], view.parameters[2]};
  if (inside_bounding_box(points, v))
    throw ParameterError("THE VIEW POINT IS INSIDE THE SURFACE'S BOX");
}

Array projected(Vec3View points, std::vector<std::size_t> shape, const View& view, Vec3 centre) {
  Array out(std::move(shape));
  try {
    project(view, centre, points, as_point2(out));
  } catch (const DataError& e) {
    throw worded(e);
  }
  return out;
}

}  // namespace

const Prompt projection_prompt{"PROJECTION?",
                               "CONIC, ISOMETRIC, ASSONOMETRIC or ORTHOGONAL (abbreviations\n"
                               "allowed); its parameters may follow.",
                               projections};

std::span<const Prompt* const> view_questions() {
  static const Prompt* const questions[] = {&projection_prompt, &conic_prompt, &isometric_prompt,
                                            &assonometric_prompt, &orthogonal_prompt};
  return questions;
}

std::span<const Choice> projection_choices() {
  return projections;
}

std::span<const Choice> plane_choices() {
  return planes;
}

std::string_view projection_word(Projection projection) {
  for (const Choice& c : projections)
    if (c.code == static_cast<int>(projection)) return c.word;
  return "PROJECTION";
}

std::string_view plane_word(double code) {
  for (const Choice& c : planes)
    if (c.code == code) return c.word;
  return "?";
}

const Prompt& parameters_prompt(Projection projection) {
  switch (projection) {
    case Projection::conic:
      return conic_prompt;
    case Projection::isometric:
      return isometric_prompt;
    case Projection::assonometric:
      return assonometric_prompt;
    case Projection::orthogonal:
      break;
  }
  return orthogonal_prompt;
}

View parse_view(Projection projection, std::span<const std::string> words) {
  View view{projection, {}};
  switch (projection) {
    case Projection::orthogonal: {
      // The plane is always both letters: X alone would be ambiguous.
      const Choice* plane =
          words.size() == 1 && words[0].size() == 2 ? choose(planes, words[0]) : nullptr;
      if (!plane) throw ParameterError("THE PLANE IS XY, YZ OR XZ");
      view.parameters[0] = plane->code;
      return view;
    }
    case Projection::conic: {
      auto v = numbers(words);
      if (v.size() != 3) throw ParameterError("GIVE THE VIEW POINT AS X Y Z");
      std::copy(v.begin(), v.end(), view.parameters.begin());
      return view;
    }
    case Projection::isometric: {
      auto v = numbers(words);
      if (v.size() != 2) throw ParameterError("GIVE THE AXIS (1, 2 OR 3) AND THE ANGLE");
      if (!parse_integer(words[0], 1, 3)) throw ParameterError("THE AXIS IS 1, 2 OR 3 (X, Y, Z)");
      if (!isom_parameters_valid(v[0], v[1])) throw ParameterError("THE ANGLE MUST BE 0 TO 90");
      std::copy(v.begin(), v.end(), view.parameters.begin());
      return view;
    }
    case Projection::assonometric: {
      auto v = numbers(words);
      if (v.size() != 3) throw ParameterError("GIVE THREE ANGLES");
      for (double a : v)
        if (!(a > 90 && a < 180)) throw ParameterError("EACH ANGLE MUST BE BETWEEN 90 AND 180");
      if (!asson_parameters_valid({v[0], v[1], v[2]}))
        throw ParameterError("THE THREE ANGLES MUST ADD UP TO 360");
      std::copy(v.begin(), v.end(), view.parameters.begin());
      return view;
    }
  }
  throw ParameterError();
}

Image input_image(const Workspace& ws, const View& view) {
  auto points = as_vec3(ws.inppn);
  check_view_point(view, points);
  const Vec3 centre = bounding_box_centre(points);
  Image image;
  image.desim = {0, view.projection, view.parameters};
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
  const std::size_t curve_rows = 2 * static_cast<std::size_t>(ws.nocur);
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
    double p[4];
    try {
      project(view, centre, Vec3View(ends, 2), MutablePoint2View(p, 2));
    } catch (const DataError& e) {
      throw worded(e);
    }
    arrows.insert(arrows.end(), {p[0], p[1], (p[2] - p[0]) / h, (p[3] - p[1]) / h, double(k),
                                 r < curve_rows ? 1.0 : 0.0});
  }
  if (!arrows.empty()) {
    image.arrows.shape = {arrows.size() / 6, 6};
    image.arrows.ravel = std::move(arrows);
  }
  return image;
}

Image surface_image(const Workspace& ws, const View& view) {
  auto points = as_vec3(ws.intpn);
  check_view_point(view, points);
  Image image;
  image.desim = {1, view.projection, view.parameters};
  image.points = projected(points, {ws.intpn.shape[0], ws.intpn.shape[1], 2}, view,
                           bounding_box_centre(as_vec3(ws.inppn)));
  return image;
}

Image ask_image(Context& ctx, Image (*make)(const Workspace&, const View&)) {
  const Choice* projection =
      ask_for(ctx, projection_prompt, [&](const std::vector<std::string>& w) {
        const Choice* c = choose(projections, w[0]);
        if (!c)
          throw ParameterError("THE PROJECTION IS CONIC, ISOMETRIC, ASSONOMETRIC OR ORTHOGONAL");
        // Whatever followed the projection's word answers the next question.
        ctx.unread(std::vector<std::string>(w.begin() + 1, w.end()));
        return c;
      });
  const auto kind = static_cast<Projection>(projection->code);
  return ask_for(ctx, parameters_prompt(kind), [&](const std::vector<std::string>& w) {
    return make(ctx.workspace(), parse_view(kind, w));
  });
}

}  // namespace igds
