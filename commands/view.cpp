#include "commands/view.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "commands/answers.h"
#include "commands/reports.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/project.h"
#include "workspace/numbers/typed.h"

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
                          "The eye's position x y z, outside the surface; the picture looks "
                          "at the centre of the input points."};
const Prompt isometric_prompt{"AXIS AND ANGLE?",
                              "The axis to drop (1 x, 2 y, 3 z) and the angle of its "
                              "projection, 0 to 90 degrees."};
const Prompt assonometric_prompt{"THREE ANGLES?",
                                 "The angles between the projected x-y, y-z and z-x axes, each "
                                 "between 90 and 180, sum 360 (try 110 130 120)."};
const Prompt orthogonal_prompt{"PLANE XY, YZ OR XZ?", "The plane to project on: XY, YZ or XZ.",
                               planes};

std::vector<double> numbers(std::span<const std::string> words) {
  std::vector<double> values;
  for (const auto& w : words) {
    auto v = parse_typed_number(w);
    if (!v || !std::isfinite(*v)) throw ParameterError(fmt::format("{} IS NOT A NUMBER", w));
    values.push_back(*v);
  }
  return values;
}

}  // namespace

const Prompt projection_prompt{"PROJECTION?",
                               "CONIC, ISOMETRIC, ASSONOMETRIC or ORTHOGONAL (abbreviations "
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

Image ask_image(Context& ctx, const std::function<Image(const Workspace&, const View&)>& make) {
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
    const View view = parse_view(kind, w);
    try {
      return make(ctx.workspace(), view);
    } catch (const DataError& e) {
      throw worded(e);
    }
  });
}

}  // namespace igds
