#include "commands/entries.h"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "commands/answers.h"
#include "workspace/error.h"
#include "workspace/kernels/marks.h"
#include "workspace/numbers/typed.h"

namespace igds {

namespace {

constexpr std::string_view point_form = "A POINT ENTRY IS K X Y Z [X Y Z ...]";
constexpr std::string_view tangent_form = "A TANGENT ENTRY IS K TX TY TZ (AND 1 OR 0 AT A CORNER)";
constexpr std::string_view finish_entries = "END THE ENTRIES WITH AN EMPTY LINE FIRST";

// The word of the AUTO entry at TANGENTS? (offered by completion there).
constexpr Choice auto_entry[] = {
    {"AUTO", 0, {}, "every border tangent by Marks's rule (ends made parabolas)"}};

// The reason for an entry whose first word is not a number: a command typed too early, or the
// form the entry must have.
[[noreturn]] void refuse_form(std::span<const std::string_view> words, std::string_view form) {
  if (!words.empty() && !parse_typed_number(words[0])) {
    std::string reason = command_word_reason(words[0], finish_entries);
    if (!reason.empty()) throw EntryError(reason);
  }
  throw EntryError(form);
}

}  // namespace

void apply_point_entry(std::span<const std::string_view> words, Array& inppn, Edits* edits) {
  const long long count = static_cast<long long>(inppn.size() / 3);
  if (words.size() < 4 || (words.size() - 1) % 3 != 0) refuse_form(words, point_form);
  auto k = parse_integer(words[0], 1, count);
  if (!k) {
    if (!parse_typed_number(words[0])) refuse_form(words, point_form);
    throw EntryError(fmt::format("THE POINT NUMBER MUST BE 1 TO {}", count));
  }
  const long long triplets = static_cast<long long>(words.size() - 1) / 3;
  if (*k + triplets - 1 > count) throw EntryError(fmt::format("THERE ARE ONLY {} POINTS", count));
  std::vector<double> values;
  values.reserve(words.size() - 1);
  for (std::size_t i = 1; i < words.size(); ++i) {
    auto v = parse_typed_number(words[i]);
    if (!v) throw EntryError(fmt::format("{} IS NOT A NUMBER", words[i]));
    if (!std::isfinite(*v)) {
      long long point = *k + static_cast<long long>(i - 1) / 3;
      throw EntryError(fmt::format("POINT {} IS NOT A FINITE NUMBER", point));
    }
    values.push_back(*v);
  }
  // Only a fully correct entry changes anything.
  const auto first = static_cast<std::size_t>(*k - 1) * 3;
  std::copy(values.begin(), values.end(), inppn.ravel.begin() + static_cast<std::ptrdiff_t>(first));
  if (edits) edits->part(first, first + values.size());
}

int tangent_row(int k, bool along_curve, int nocur, int nostr) {
  const int curve = (k - 1) / nostr, place = (k - 1) % nostr;
  if (along_curve) {
    if (nostr == 1) return -1;  // a curve of one point has no direction
    if (place == 0) return 2 * curve;
    if (place == nostr - 1) return 2 * curve + 1;
    return -1;
  }
  if (nocur == 1) return -1;
  if (curve == 0) return 2 * nocur + 2 * place;
  if (curve == nocur - 1) return 2 * nocur + 2 * place + 1;
  return -1;
}

Array zero_tangents(int nocur, int nostr) {
  Array inptg({static_cast<std::size_t>(2 * (nocur + nostr)), 4});
  for (int k = 1; k <= nocur * nostr; ++k) {
    for (bool along_curve : {true, false}) {
      int row = tangent_row(k, along_curve, nocur, nostr);
      if (row >= 0) inptg.ravel[static_cast<std::size_t>(row) * 4 + 3] = k;
    }
  }
  return inptg;
}

void apply_tangent_entry(std::span<const std::string_view> words, int nocur, int nostr,
                         Array& inptg, Edits* edits) {
  if (words.size() != 4 && words.size() != 5) refuse_form(words, tangent_form);
  const long long count = static_cast<long long>(nocur) * nostr;
  auto k = parse_integer(words[0], 1, count);
  if (!k) {
    if (!parse_typed_number(words[0])) refuse_form(words, tangent_form);
    throw EntryError(fmt::format("THE POINT NUMBER MUST BE 1 TO {}", count));
  }
  const int point = static_cast<int>(*k);
  std::array<double, 3> t{};
  for (std::size_t i = 0; i < 3; ++i) {
    auto v = parse_typed_number(words[i + 1]);
    if (!v) throw EntryError(fmt::format("{} IS NOT A NUMBER", words[i + 1]));
    if (!std::isfinite(*v))
      throw EntryError(fmt::format("THE TANGENT AT POINT {} IS NOT A FINITE NUMBER", point));
    t[i] = *v;
  }
  const int curve_row = tangent_row(point, true, nocur, nostr);
  const int stringer_row = tangent_row(point, false, nocur, nostr);
  int row = -1;
  if (curve_row >= 0 && stringer_row >= 0) {
    if (words.size() != 5)
      throw EntryError(fmt::format("POINT {} IS A CORNER: GIVE 1 (CURVE) OR 0 (STRINGER)", point));
    auto f = parse_integer(words[4], 0, 1);
    if (!f) throw EntryError("THE LAST NUMBER AT A CORNER MUST BE 1 (CURVE) OR 0 (STRINGER)");
    row = *f == 1 ? curve_row : stringer_row;
  } else {
    if (curve_row < 0 && stringer_row < 0)
      throw EntryError(fmt::format("POINT {} IS NOT ON THE BORDER", point));
    if (words.size() != 4)
      throw EntryError(fmt::format("POINT {} IS NOT A CORNER: GIVE K TX TY TZ", point));
    row = curve_row >= 0 ? curve_row : stringer_row;
  }
  double* r = inptg.data() + static_cast<std::size_t>(row) * 4;
  r[0] = t[0];
  r[1] = t[1];
  r[2] = t[2];
  r[3] = point;
  if (edits) edits->part(static_cast<std::size_t>(row) * 4, static_cast<std::size_t>(row) * 4 + 4);
}

void apply_auto_tangents(int nocur, int nostr, const Array& inppn, Array& inptg, Edits* edits) {
  inptg = marks_border_tangents(nocur, nostr, as_vec3(inppn));
  if (edits) edits->all();
}

bool is_auto_entry(std::span<const std::string_view> words) {
  return words.size() == 1 && choose(auto_entry, words[0]) != nullptr;
}

GridSize parse_grid_size(std::span<const std::string_view> words) {
  constexpr std::string_view form = "GIVE TWO WHOLE NUMBERS, NOCUR AND NOSTR";
  if (words.size() != 2) refuse_form(words, form);
  const auto limit = static_cast<long long>(max_input_points);
  auto nocur = parse_integer(words[0], 1, limit);
  auto nostr = parse_integer(words[1], 1, limit);
  if (!nocur || !nostr) refuse_form(words, form);
  if (*nocur * *nostr < 2) throw EntryError("A SURFACE NEEDS AT LEAST TWO POINTS");
  if (*nocur * *nostr > limit)
    throw EntryError(fmt::format("{} POINTS, AT MOST {}", *nocur * *nostr, max_input_points));
  return GridSize{static_cast<int>(*nocur), static_cast<int>(*nostr)};
}

Density parse_density(std::span<const std::string_view> words, int nocur, int nostr) {
  constexpr std::string_view form = "GIVE TWO WHOLE NUMBERS >= 0, INTCU AND INTST";
  if (words.size() != 2) refuse_form(words, form);
  const auto limit = static_cast<long long>(max_grid_points);
  auto intcu = parse_integer(words[0], 0, limit);
  auto intst = parse_integer(words[1], 0, limit);
  if (!intcu || !intst) refuse_form(words, form);
  const double points = grid_points(nocur, nostr, double(*intcu), double(*intst));
  if (points > double(max_grid_points))
    throw EntryError(
        fmt::format("THE GRID WOULD HAVE {:.0f} POINTS, AT MOST {}", points, max_grid_points));
  return {static_cast<int>(*intcu), static_cast<int>(*intst)};
}

const Prompt size_prompt{"NUMBER OF CURVES AND STRINGERS?",
                         "Two whole numbers: NOCUR, the input curves, and NOSTR, the input "
                         "stringers (points on each curve); 1 3 is a single curve of 3 points."};
const Prompt points_prompt{"POINTS?",
                           "A point number k and x y z (more triplets go to k+1, k+2, ...); an "
                           "empty line ends the points."};
const Prompt tangents_prompt{
    "TANGENTS?",
    "A border point k and tx ty tz, and at a corner 1 (along the curve) or 0 "
    "(along the stringer); AUTO: all from the points; an empty line ends.",
    auto_entry};
const Prompt density_prompt{
    "INTERPOLATED CURVES AND STRINGERS?",
    "Two whole numbers >= 0: the curves to insert between two input curves, "
    "and the stringers between two input stringers."};

GridSize ask_grid_size(Context& ctx) {
  return ask_for(ctx, size_prompt, [](const std::vector<std::string>& w) {
    return parse_grid_size(std::vector<std::string_view>(w.begin(), w.end()));
  });
}

void ask_point_entries(Context& ctx, Array& inppn, Edits* edits) {
  for (;;) {
    const auto words = ctx.ask_words(points_prompt);
    if (words.empty()) return;
    try {
      apply_point_entry(words, inppn, edits);
    } catch (const EntryError& e) {
      ctx.report(e.what());
    }
  }
}

bool ask_tangent_entries(Context& ctx, int nocur, int nostr, const Array& inppn, Array& inptg,
                         Edits* edits) {
  bool automatic = false;
  for (;;) {
    const auto words = ctx.ask_words(tangents_prompt);
    if (words.empty()) return automatic;
    if (is_auto_entry(words)) {
      apply_auto_tangents(nocur, nostr, inppn, inptg, edits);
      automatic = true;
      continue;
    }
    try {
      apply_tangent_entry(words, nocur, nostr, inptg, edits);
    } catch (const EntryError& e) {
      ctx.report(e.what());
    }
  }
}

Density ask_density(Context& ctx, int nocur, int nostr) {
  for (;;) {
    const auto words = ctx.ask_words(density_prompt);
    if (words.empty()) continue;
    try {
      return parse_density(words, nocur, nostr);
    } catch (const EntryError& e) {
      ctx.report(e.what());
    }
  }
}

}  // namespace igds
