#include "workspace/variables.h"

#include <atomic>
#include <cmath>

#include <fmt/format.h>

#include "workspace/kernels/data_error.h"
#include "workspace/kernels/limits.h"

namespace igds {

namespace {

constexpr VariableInfo table[] = {
    {Variable::nocur, "NOCUR", Kept::surface_number, true, 0, "", "number of input curves"},
    {Variable::nostr, "NOSTR", Kept::surface_number, true, 0, "", "number of input stringers"},
    {Variable::intcu, "INTCU", Kept::surface_number, true, 0, "",
     "curves interpolated between two input curves"},
    {Variable::intst, "INTST", Kept::surface_number, true, 0, "",
     "stringers interpolated between two input stringers"},
    {Variable::inppn, "INPPN", Kept::input, false, 2, "(NOCUR x NOSTR) x 3",
     "the input points x y z, in point-number order"},
    {Variable::inptg, "INPTG", Kept::input, false, 2, "2(NOCUR+NOSTR) x 4",
     "the border tangents x y z and their point number"},
    {Variable::patches, "PATCHES", Kept::derived, false, 5, "(NOCUR-1) x (NOSTR-1) x 3 x 4 x 4",
     "the bicubic patches, one 4 x 4 matrix per coordinate"},
    {Variable::intpn, "INTPN", Kept::derived, false, 3,
     "(NOCUR+INTCU(NOCUR-1)) x (NOSTR+INTST(NOSTR-1)) x 3", "the interpolated points"},
    {Variable::image, "IMAGE", Kept::image_points, false, 3, "planes x rows x 2",
     "the current image"},
    {Variable::desim, "DESIM", Kept::image_view, false, 1, "5",
     "what IMAGE shows and its projection"},
    {Variable::temp1, "TEMP1", Kept::image_points, false, 3, "planes x rows x 2",
     "the image of STORE FIRST"},
    {Variable::dest1, "DEST1", Kept::image_view, false, 1, "5", "the description of TEMP1"},
    {Variable::temp2, "TEMP2", Kept::image_points, false, 3, "planes x rows x 2",
     "the image of STORE SECOND"},
    {Variable::dest2, "DEST2", Kept::image_view, false, 1, "5", "the description of TEMP2"},
    {Variable::status, "STATUS", Kept::status, true, 1, "10",
     "HELP LONG or SHORT, the keyboard of the last PLOT, reserved"},
};

std::string shape_words(const std::vector<std::size_t>& shape) {
  if (shape.empty()) return "EMPTY";
  std::string s;
  for (std::size_t k = 0; k < shape.size(); ++k) s += (k ? " BY " : "") + std::to_string(shape[k]);
  return s;
}

std::optional<VariableProblem> wrong_shape(Variable v, const Array& a,
                                           const std::vector<std::size_t>& expected) {
  if (a.shape == expected) return std::nullopt;
  return VariableProblem{v, fmt::format("{} IS {}, NOT {}", info(v).name, shape_words(a.shape),
                                        shape_words(expected))};
}

}  // namespace

ImageRef::ImageRef(std::shared_ptr<const Image> image) {
  if (image) cell_ = std::make_shared<const Cell>(Cell{std::move(image), nullptr, 0, {}});
}

ImageRef ImageRef::deferred(std::function<Image()> make, std::uint64_t drawn_from,
                            const Description& desim) {
  ImageRef r;
  r.cell_ = std::make_shared<const Cell>(Cell{nullptr, std::move(make), drawn_from, desim});
  return r;
}

std::optional<std::pair<std::uint64_t, Description>> ImageRef::recipe() const {
  if (!cell_) return std::nullopt;
  const Image* made = cell_->image.get();
  const std::uint64_t from = made ? made->drawn_from : cell_->drawn_from;
  if (from == 0) return std::nullopt;
  return std::pair{from, made ? made->desim : cell_->desim};
}

bool ImageRef::same_recipe(const ImageRef& other) const {
  const auto mine = recipe();
  if (!mine || mine != other.recipe()) return false;
  // An image not made yet is made whole (a recipe has no window).
  const Image *a = cell_->image.get(), *b = other.cell_->image.get();
  return (a ? a->window : std::nullopt) == (b ? b->window : std::nullopt);
}

const Image& ImageRef::get() const {
  if (!cell_->image) {
    // A make that throws leaves the recipe: the next look tries again, and meets the same error.
    cell_->image = std::make_shared<const Image>(cell_->make());
    cell_->make = nullptr;  // and what it held
  }
  return *cell_->image;
}

std::uint64_t new_generation() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

std::span<const VariableInfo> variables() {
  return table;
}

const VariableInfo& info(Variable v) {
  return table[static_cast<std::size_t>(v)];
}

const VariableInfo* find_variable(std::string_view name) {
  for (const auto& v : table)
    if (v.name == name) return &v;
  return nullptr;
}

std::vector<std::size_t> expected_shape(const Workspace& ws, Variable v) {
  const auto cu = static_cast<std::size_t>(std::max(ws.nocur, 0));
  const auto st = static_cast<std::size_t>(std::max(ws.nostr, 0));
  const auto ic = static_cast<std::size_t>(std::max(ws.intcu, 0));
  const auto is = static_cast<std::size_t>(std::max(ws.intst, 0));
  switch (v) {
    case Variable::inppn:
      return {cu * st, 3};
    case Variable::inptg:
      return {2 * (cu + st), 4};
    case Variable::patches:
      return {cu ? cu - 1 : 0, st ? st - 1 : 0, 3, 4, 4};
    case Variable::intpn:
      return {cu + ic * (cu ? cu - 1 : 0), st + is * (st ? st - 1 : 0), 3};
    case Variable::desim:
    case Variable::dest1:
    case Variable::dest2:
      return {5};
    case Variable::status:
      return {10};
    default:
      return {};
  }
}

namespace {

// The report of number k of `a`, the first that is not finite (a.size(): none, no report).
std::optional<VariableProblem> not_finite_at(Variable v, const Array& a, std::size_t k) {
  if (k == a.size()) return std::nullopt;
  const std::string_view name = info(v).name;
  const auto& s = a.shape;
  std::string where;
  if (v == Variable::inppn && s.size() == 2 && s[1] > 0) {
    where = fmt::format("POINT {} OF {}", k / s[1] + 1, name);
  } else if (v == Variable::patches && s.size() == 5) {
    where = fmt::format("PATCH {} OF {}", k / 48 + 1, name);
  } else if (s.size() == 3 && s[1] > 0 && s[2] > 0) {
    const std::size_t point = k / s[2];
    where = v == Variable::intpn
                ? fmt::format("ROW {} COLUMN {} OF {}", point / s[1] + 1, point % s[1] + 1, name)
                : fmt::format("PLANE {} ROW {} OF {}", point / s[1] + 1, point % s[1] + 1, name);
  } else if (s.size() == 2 && s[1] > 0) {
    where = fmt::format("ROW {} OF {}", k / s[1] + 1, name);
  } else if (s.size() == 1) {
    where = fmt::format("{}[{}]", name, k + 1);
  } else {
    where = fmt::format("NUMBER {} OF {}", k + 1, name);
  }
  return VariableProblem{v, where + " IS NOT A FINITE NUMBER"};
}

}  // namespace

std::optional<VariableProblem> finite_problem(Variable v, const Array& a) {
  return not_finite_at(v, a, first_not_finite(a.data(), a.size()));
}

std::string made_surface_reason(const DataError& e) {
  switch (e.problem) {
    case DataError::Problem::patch_not_finite:
      return fmt::format("PATCH {} IS NOT A FINITE NUMBER", e.number);
    case DataError::Problem::grid_point_not_finite:
      return fmt::format("INTPN ROW {} COLUMN {} IS NOT A FINITE NUMBER", e.number, e.column);
    default:
      return "THE SURFACE CANNOT BE INTERPOLATED";
  }
}

std::optional<VariableProblem> size_problem(int nocur, int nostr, int intcu, int intst) {
  if (nocur < 1 || nostr < 1)
    return VariableProblem{nocur < 1 ? Variable::nocur : Variable::nostr,
                           "NOCUR AND NOSTR MUST BE AT LEAST 1"};
  if (double(nocur) * nostr < 2)
    return VariableProblem{Variable::nostr, "A SURFACE NEEDS AT LEAST TWO POINTS"};
  if (double(nocur) * nostr > double(max_input_points))
    return VariableProblem{Variable::nocur, fmt::format("{:.0f} INPUT POINTS, MORE THAN {}",
                                                        double(nocur) * nostr, max_input_points)};
  if (intcu < 0 || intst < 0)
    return VariableProblem{intcu < 0 ? Variable::intcu : Variable::intst,
                           "INTCU AND INTST MUST BE AT LEAST 0"};
  const double points = grid_points(nocur, nostr, intcu, intst);
  if (points > double(max_grid_points))
    return VariableProblem{Variable::intcu, fmt::format("{:.0f} INTERPOLATED POINTS, MORE THAN {}",
                                                        points, max_grid_points)};
  return std::nullopt;
}

std::optional<VariableProblem> surface_problem(const Workspace& ws, bool allow_empty_surface) {
  if (ws.nocur == 0) {
    const bool empty = ws.nostr == 0 && ws.intcu == 0 && ws.intst == 0 && ws.inppn.empty() &&
                       ws.inptg.empty() && ws.patches.empty() && ws.intpn.empty();
    if (empty) return std::nullopt;
    return VariableProblem{Variable::nocur, "NOCUR IS 0 BUT THERE IS A SURFACE"};
  }
  if (auto p = size_problem(ws.nocur, ws.nostr, ws.intcu, ws.intst)) return p;
  for (Variable v : {Variable::inppn, Variable::inptg})
    if (auto p = wrong_shape(v, v == Variable::inppn ? ws.inppn : ws.inptg, expected_shape(ws, v)))
      return p;
  if (auto p = finite_problem(Variable::inppn, ws.inppn)) return p;
  if (auto p = finite_problem(Variable::inptg, ws.inptg)) return p;
  // Column 4 of INPTG: the number of an input point.
  for (std::size_t r = 0; r < ws.inptg.shape[0]; ++r) {
    const double k = ws.inptg.ravel[4 * r + 3];
    if (k != std::floor(k) || k < 0 || k > double(ws.nocur) * ws.nostr)
      return VariableProblem{Variable::inptg,
                             fmt::format("ROW {} OF INPTG NAMES NO INPUT POINT", r + 1)};
  }
  const bool none =
      ws.patches.empty() && ws.intpn.empty() && ws.patches.shape.empty() && ws.intpn.shape.empty();
  if (none && allow_empty_surface) return std::nullopt;
  // The interpolation's surface keeps no PATCHES (state.h).
  const bool made_when_read =
      ws.changes.derived && ws.patches.shape.empty() && ws.nocur > 1 && ws.nostr > 1;
  if (auto p = wrong_shape(Variable::patches, ws.patches, expected_shape(ws, Variable::patches));
      p && !made_when_read)
    return p;
  return wrong_shape(Variable::intpn, ws.intpn, expected_shape(ws, Variable::intpn));
}

std::optional<VariableProblem> image_problem(const Image& image, Variable points,
                                             std::optional<std::array<double, 4>>* extent) {
  const auto view = static_cast<Variable>(static_cast<int>(points) + 1);
  const auto& d = image.desim;
  if (d.what == 2 && !image.picture)
    return VariableProblem{
        view, fmt::format("{}[1] IS 2 BUT THE IMAGE IS NOT A DUCT PICTURE", info(view).name)};
  if (d.what < 0 || d.what > 3)
    return VariableProblem{view, fmt::format("{}[1] IS NOT 0, 1, 2 OR 3", info(view).name)};
  if (d.hidden && d.what != 1)
    return VariableProblem{view, fmt::format("{} IS NOT A SURFACE: ITS HIDDEN LINES CANNOT BE "
                                             "REMOVED",
                                             info(points).name)};
  // A picture image is its drawing, made from its text as its DESIM says: neither is assigned.
  if (image.picture && (d != image.picture->desim || !image.points.empty()))
    return VariableProblem{points,
                           fmt::format("{} IS A DUCT PICTURE: {} AND {} CANNOT BE CHANGED "
                                       "(DISPLAY PICTURE MAKES ANOTHER)",
                                       info(points).name, info(points).name, info(view).name)};
  const int p = static_cast<int>(d.projection);
  if (p < 1 || p > 4)
    return VariableProblem{view,
                           fmt::format("{}[2] IS NOT A PROJECTION (1 TO 4)", info(view).name)};
  for (std::size_t k = 0; k < d.parameters.size(); ++k)
    if (!std::isfinite(d.parameters[k]))
      return VariableProblem{view,
                             fmt::format("{}[{}] IS NOT A FINITE NUMBER", info(view).name, k + 3)};
  const auto& s = image.points.shape;
  if (!(s.empty() || (s.size() == 3 && s[2] == 2)))
    return VariableProblem{points, fmt::format("{} IS {}, NOT PLANES BY ROWS BY 2",
                                               info(points).name, shape_words(s))};
  if (!s.empty() && double(s[0]) * double(s[1]) > double(max_grid_points))
    return VariableProblem{
        points, fmt::format("{} HAS MORE THAN {} POINTS", info(points).name, max_grid_points)};
  const auto& a = image.arrows.shape;
  if (!(a.empty() || (a.size() == 2 && (a[1] == 6 || a[1] == 4))))
    return VariableProblem{points, fmt::format("THE ARROWS OF {} ARE {}, NOT K BY 6",
                                               info(points).name, shape_words(a))};
  // Combs: none (an IMAGE assigned in APL), or two ends for every point.
  const auto& c = image.combs.shape;
  if (d.what != 3 && !c.empty())
    return VariableProblem{
        view, fmt::format("{}[1] IS NOT 3 BUT {} HAS COMBS", info(view).name, info(points).name)};
  if (!c.empty() && !(s.size() == 3 && c == std::vector<std::size_t>{s[0], s[1], 4}))
    return VariableProblem{
        points, fmt::format("THE COMBS OF {} ARE {}, NOT {} BY 4", info(points).name,
                            shape_words(c), shape_words(s.empty() ? s : std::vector{s[0], s[1]}))};
  if (!std::isfinite(image.comb_scale) || image.comb_scale < 0)
    return VariableProblem{points, fmt::format("THE COMB SCALE OF {} IS NOT A FINITE NUMBER, 0 OR "
                                               "MORE",
                                               info(points).name)};
  if (const std::size_t k = first_not_finite(image.combs.data(), image.combs.size());
      k < image.combs.size())
    return VariableProblem{
        points, fmt::format("COMB {} OF {} IS NOT A FINITE NUMBER", k / 2 + 1, info(points).name)};
  if (extent && !image.points.empty()) {
    // The box of the points found in the same pass as their check.
    const FinitePoints found = finite_points(image.points.data(), image.points.size() / 2);
    if (auto q = not_finite_at(points, image.points, found.not_finite)) return q;
    *extent = found.box;
  } else if (auto q = finite_problem(points, image.points)) {
    return q;
  }
  // A hidden-line image made now has no points yet (a recipe); one read has one nearness each.
  const auto& n = image.nearness.shape;
  const bool nearness_fits = image.desim.hidden
                                 ? (s.empty() && n.empty()) ||
                                       (n.size() == 2 && !s.empty() && n[0] == s[0] && n[1] == s[1])
                                 : n.empty();
  if (!nearness_fits)
    return VariableProblem{points, fmt::format("THE DEPTHS OF {} ARE {}, NOT ONE FOR EACH POINT",
                                               info(points).name, shape_words(n))};
  if (first_not_finite(image.nearness.data(), image.nearness.size()) < image.nearness.size())
    return VariableProblem{points,
                           fmt::format("A DEPTH OF {} IS NOT A FINITE NUMBER", info(points).name)};
  if (const std::size_t k = first_not_finite(image.arrows.data(), image.arrows.size());
      k < image.arrows.size())
    return VariableProblem{points, fmt::format("ARROW {} OF {} IS NOT A FINITE NUMBER",
                                               k / a[1] + 1, info(points).name)};
  return std::nullopt;
}

std::optional<VariableProblem> status_problem(const std::array<int, 10>& status) {
  if (status[0] != 0 && status[0] != 1)
    return VariableProblem{Variable::status, "STATUS[1] IS NOT 0 OR 1"};
  if (status[1] < 0 || status[1] > 2)
    return VariableProblem{Variable::status, "STATUS[2] IS NOT 0, 1 OR 2"};
  // CHANGE TWISTS (1: MARKS) and AUTO at TANGENTS? (1: set by Marks's rule).
  if (status[Workspace::status_twists] != 0 && status[Workspace::status_twists] != 1)
    return VariableProblem{Variable::status, "STATUS[3] IS NOT 0 OR 1"};
  if (status[Workspace::status_auto] != 0 && status[Workspace::status_auto] != 1)
    return VariableProblem{Variable::status, "STATUS[4] IS NOT 0 OR 1"};
  return std::nullopt;
}

}  // namespace igds
