#include "commands/entries.h"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "commands/command.h"
#include "commands/reports.h"
#include "workspace/apl.h"
#include "workspace/error.h"
#include "workspace/kernels/data_error.h"

namespace igds {

namespace {

std::string entry_error(std::string_view why) {
  return fmt::format("{}: {}", reports::incorrect_entry, why);
}

}  // namespace

std::optional<long long> parse_integer(std::string_view word, long long low, long long high) {
  auto value = parse_apl_number(word);
  if (!value || !std::isfinite(*value) || std::floor(*value) != *value) return std::nullopt;
  if (*value < static_cast<double>(low) || *value > static_cast<double>(high)) return std::nullopt;
  return static_cast<long long>(*value);
}

EntryOutcome apply_point_entry(std::span<const std::string> words, Array& inppn) {
  const long long count = static_cast<long long>(inppn.size() / 3);
  if (words.size() < 4 || (words.size() - 1) % 3 != 0) return reports::incorrect_entry;
  auto k = parse_integer(words[0], 1, count);
  if (!k) return entry_error(fmt::format("THE POINT NUMBER MUST BE 1 TO {}", count));
  const long long triplets = static_cast<long long>(words.size() - 1) / 3;
  if (*k + triplets - 1 > count) return entry_error(fmt::format("THERE ARE ONLY {} POINTS", count));
  std::vector<double> values;
  values.reserve(words.size() - 1);
  for (std::size_t i = 1; i < words.size(); ++i) {
    auto v = parse_apl_number(words[i]);
    if (!v) return reports::incorrect_entry;
    if (!std::isfinite(*v)) {
      long long point = *k + static_cast<long long>(i - 1) / 3;
      return entry_error(fmt::format("POINT {} IS NOT A FINITE NUMBER", point));
    }
    values.push_back(*v);
  }
  // Only a fully correct entry changes anything.
  std::copy(values.begin(), values.end(), inppn.ravel.begin() + (*k - 1) * 3);
  return std::nullopt;
}

int tangent_row(int k, bool along_curve, int nocur, int nostr) {
  const int curve = (k - 1) / nostr, place = (k - 1) % nostr;
  if (along_curve) {
    if (place == 0) return 2 * curve;
    if (place == nostr - 1) return 2 * curve + 1;
    return -1;
  }
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

EntryOutcome apply_tangent_entry(std::span<const std::string> words, int nocur, int nostr,
                                 Array& inptg) {
  if (words.size() != 4 && words.size() != 5) return reports::incorrect_entry;
  const long long count = static_cast<long long>(nocur) * nostr;
  auto k = parse_integer(words[0], 1, count);
  if (!k) return entry_error(fmt::format("THE POINT NUMBER MUST BE 1 TO {}", count));
  const int point = static_cast<int>(*k);
  std::array<double, 3> t{};
  for (std::size_t i = 0; i < 3; ++i) {
    auto v = parse_apl_number(words[i + 1]);
    if (!v) return reports::incorrect_entry;
    if (!std::isfinite(*v))
      return entry_error(fmt::format("THE TANGENT AT POINT {} IS NOT A FINITE NUMBER", point));
    t[i] = *v;
  }
  const int curve_row = tangent_row(point, true, nocur, nostr);
  const int stringer_row = tangent_row(point, false, nocur, nostr);
  int row = -1;
  if (curve_row >= 0 && stringer_row >= 0) {
    if (words.size() != 5)
      return entry_error(
          fmt::format("POINT {} IS A CORNER: GIVE 1 (CURVE) OR 0 (STRINGER)", point));
    auto f = parse_integer(words[4], 0, 1);
    if (!f) return entry_error("THE LAST NUMBER AT A CORNER MUST BE 1 (CURVE) OR 0 (STRINGER)");
    row = *f == 1 ? curve_row : stringer_row;
  } else {
    if (curve_row < 0 && stringer_row < 0)
      return entry_error(fmt::format("POINT {} IS NOT ON THE BORDER", point));
    if (words.size() != 4)
      return entry_error(fmt::format("POINT {} IS NOT A CORNER: GIVE K TX TY TZ", point));
    row = curve_row >= 0 ? curve_row : stringer_row;
  }
  double* r = inptg.data() + static_cast<std::size_t>(row) * 4;
  r[0] = t[0];
  r[1] = t[1];
  r[2] = t[2];
  r[3] = point;
  return std::nullopt;
}

std::optional<GridSize> parse_grid_size(std::span<const std::string> words) {
  if (words.size() != 2) return std::nullopt;
  auto nocur = parse_integer(words[0], 2, static_cast<long long>(max_input_points));
  auto nostr = parse_integer(words[1], 2, static_cast<long long>(max_input_points));
  if (!nocur || !nostr || *nocur * *nostr > static_cast<long long>(max_input_points))
    return std::nullopt;
  return GridSize{static_cast<int>(*nocur), static_cast<int>(*nostr)};
}

EntryOutcome parse_density(std::span<const std::string> words, int nocur, int nostr,
                           Density& density) {
  if (words.size() != 2) return reports::incorrect_entry;
  const auto limit = static_cast<long long>(max_grid_points);
  auto intcu = parse_integer(words[0], 0, limit);
  auto intst = parse_integer(words[1], 0, limit);
  if (!intcu || !intst) return reports::incorrect_entry;
  const double rows = nocur + static_cast<double>(*intcu) * (nocur - 1);
  const double columns = nostr + static_cast<double>(*intst) * (nostr - 1);
  if (rows * columns > static_cast<double>(max_grid_points))
    return entry_error(fmt::format("THE GRID WOULD HAVE {:.0f} POINTS, AT MOST {}", rows * columns,
                                   max_grid_points));
  density = {static_cast<int>(*intcu), static_cast<int>(*intst)};
  return std::nullopt;
}

std::optional<bool> parse_yes_no(std::span<const std::string> words) {
  static constexpr std::array<std::string_view, 2> answers{"YES", "NO"};
  if (words.size() != 1) return std::nullopt;
  int i = lookup_prefix(answers, words[0]);
  if (i < 0) return std::nullopt;
  return i == 0;
}

std::span<const std::string_view> projection_words() {
  static constexpr std::array<std::string_view, 5> words{"CONIC", "ISOMETRIC", "ASSONOMETRIC",
                                                         "ORTHOGONAL", "AXONOMETRIC"};
  return words;
}

const Prompt points_prompt{
    "POINTS?",
    "A point number k and x y z (more triplets go to k+1, k+2, ...); an empty line ends the "
    "points."};
const Prompt tangents_prompt{
    "TANGENTS?",
    "A border point number k and tx ty tz, then 1 (along the curve) or 0 (along the stringer)\n"
    "at a corner; an empty line ends the tangents."};
const Prompt density_prompt{
    "INTERPOLATED CURVES AND STRINGERS?",
    "Two whole numbers >= 0: the curves to insert between two input curves, and the stringers\n"
    "between two input stringers."};

void ask_point_entries(Context& ctx, Array& inppn) {
  for (;;) {
    auto words = ctx.ask(points_prompt);
    if (words.empty()) return;
    if (auto error = apply_point_entry(words, inppn)) ctx.report(*error);
  }
}

void ask_tangent_entries(Context& ctx, int nocur, int nostr, Array& inptg) {
  for (;;) {
    auto words = ctx.ask(tangents_prompt);
    if (words.empty()) return;
    if (auto error = apply_tangent_entry(words, nocur, nostr, inptg)) ctx.report(*error);
  }
}

Density ask_density(Context& ctx, int nocur, int nostr) {
  for (;;) {
    auto words = ctx.ask(density_prompt);
    if (words.empty()) continue;
    Density density;
    if (auto error = parse_density(words, nocur, nostr, density))
      ctx.report(*error);
    else
      return density;
  }
}

Surface interpolate_surface(int nocur, int nostr, Density density, const Array& inppn,
                            const Array& inptg) {
  SurfaceInput input{nocur, nostr, density.intcu, density.intst, &inppn, &inptg};
  try {
    return interpolate(input);
  } catch (const DataError& e) {
    throw worded(e, "THE SURFACE IS NOT CHANGED");
  }
}

void expect_no_more_words(Context& ctx) {
  if (ctx.has_pending()) throw Report(reports::incorrect_command);
}

void make_current(Workspace& ws, int nocur, int nostr, Density density, Array inppn, Array inptg,
                  Surface surface) {
  ws.nocur = nocur;
  ws.nostr = nostr;
  ws.intcu = density.intcu;
  ws.intst = density.intst;
  ws.inppn = std::move(inppn);
  ws.inptg = std::move(inptg);
  ws.patches = std::move(surface.patches);
  ws.intpn = std::move(surface.intpn);
}

}  // namespace igds
