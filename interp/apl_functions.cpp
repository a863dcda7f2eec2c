// The functions of the manual's workspace IGDS4013 (section 7) in END APL, each calling the code
// that does that work in igds (docs/interp.md, "END APL": the list and what each takes).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "commands/command.h"
#include "commands/picture.h"
#include "commands/reports.h"
#include "commands/view.h"
#include "devices/tek4013.h"
#include "interp/apl/array_bridge.h"
#include "interp/apl_args.h"
#include "interp/apl_env.h"
#include "interp/words.h"
#include "workspace/disk/disk.h"
#include "workspace/error.h"
#include "workspace/kernels/project.h"
#include "workspace/kernels/spline.h"
#include "workspace/kernels/surface.h"
#include "workspace/numbers/typed.h"
#include "workspace/variables.h"

namespace igds {

extern const Command change_command, end_command, help_command, plot_command;

namespace {

using AplError = apl::Error;
using apl::ErrorKind;
using apl::Value;
using namespace apl_args;

// The projection of `points` by one of the manual's projection functions: the same shape with 2
// on the last axis.
template <typename F>
Value projected(const Array& points, F project) {
  Array out;
  out.shape = points.shape;
  out.shape.back() = 2;
  out.ravel.assign(points.size() / 3 * 2, 0.0);
  try {
    project(as_vec3(points), as_point2(out));
  } catch (const DataError& e) {
    refuse(e);
  }
  return apl::to_value(out);
}

Value numbers_value(std::vector<double> x) {
  return Value::vector(std::span<const double>(x));
}

// --- GETCOM's codes: a command as numbers --------------------------------------------------

// The manual's commands, those before HELP in the table: COMxxx, PARxx, GETCOM.
std::vector<const Command*> manual_commands() {
  std::vector<const Command*> out;
  for (const Command* c : command_table()) {
    if (c == &help_command) break;
    out.push_back(c);
  }
  return out;
}

int command_number(const Command& command) {
  const auto table = command_table();
  return static_cast<int>(std::find(table.begin(), table.end(), &command) - table.begin()) + 1;
}

// APLNAME: a CMS name and type as five numbers, four characters in each of the first four (six
// bits each: blank 0, A-Z 1-26, 0-9 27-36, $ # @ + - _ 37-42), the fifth 0. The manual's
// APLCMS functions passed names so; this is igds's encoding of them.
constexpr std::string_view name_characters = " ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789$#@+-_";

std::vector<double> aplname(std::string_view name, std::string_view type) {
  std::string text = fmt::format("{:<8}{:<8}", name, type);
  std::vector<double> codes(5, 0);
  for (std::size_t i = 0; i < 16; ++i) {
    const std::size_t c = name_characters.find(text[i]);
    if (c == std::string_view::npos) throw AplError(ErrorKind::domain);
    codes[i / 4] = codes[i / 4] * 64 + static_cast<double>(c);
  }
  return codes;
}

// The name and type of APLNAME's numbers; DOMAIN ERROR for numbers no name gives.
std::pair<std::string, std::string> from_aplname(std::span<const double> codes) {
  if (codes.size() != 5) throw AplError(ErrorKind::length);
  std::string text(16, ' ');
  for (std::size_t n = 0; n < 4; ++n) {
    double x = codes[n];
    if (!(x >= 0 && x < 64.0 * 64 * 64 * 64) || std::floor(x) != x)
      throw AplError(ErrorKind::domain);
    auto v = static_cast<std::uint32_t>(x);
    for (std::size_t k = 4; k-- > 0;) {
      const std::uint32_t c = v % 64;
      v /= 64;
      if (c >= name_characters.size()) throw AplError(ErrorKind::domain);
      text[n * 4 + k] = name_characters[c];
    }
  }
  auto trimmed = [](std::string s) {
    s.erase(s.find_last_not_of(' ') + 1);
    return s;
  };
  std::string name = trimmed(text.substr(0, 8)), type = trimmed(text.substr(8));
  if (!cms_name(name)) throw AplError(ErrorKind::domain);
  return {name, type};
}

// A name and type typed as one text, 'HULL IGDSDATA'.
std::pair<std::string, std::string> name_and_type(Args v) {
  const std::vector<std::string> words = words_of(v);
  if (words.empty() || words.size() > 2) throw AplError(ErrorKind::length);
  auto name = cms_name(words[0]);
  auto type = words.size() == 2 ? cms_name(words[1]) : std::optional<std::string>("");
  if (!name || !type) throw AplError(ErrorKind::domain);
  return {*name, *type};
}

// What an option or a command takes after it, from its declaration ("[name]",
// "[projection [parameters]]", "[ZERO|MARKS]").
struct Takes {
  bool name = false, projection = false;
  std::vector<std::string> choices;
};
Takes takes(std::string_view follows) {
  Takes t;
  t.name = follows.find("name") != std::string_view::npos;
  t.projection = follows.find("projection") != std::string_view::npos;
  if (follows.find('|') != std::string_view::npos) {
    std::string words(follows);
    for (char& c : words)
      if (c == '[' || c == ']' || c == '|') c = ' ';
    t.choices = split_words(words);
  }
  return t;
}

// The codes of the words after a command (PARxx, GETCOM). A word the command does not take is
// DOMAIN ERROR with the command's own report.
std::vector<double> encode(const Command& command, std::span<const std::string> words) {
  std::vector<double> codes;
  std::size_t i = 0;
  std::string_view follows = command.follows;
  if (!command.options.empty()) {
    const Choice* option = words.empty() ? nullptr : choose(command.options, words[0]);
    if (!option) throw AplError(ErrorKind::domain, command.bad_option);
    codes.push_back(static_cast<double>(option - command.options.data()) + 1);
    follows = option->follows;
    i = 1;
  }
  const Takes t = takes(follows);
  if (t.name && i < words.size()) {
    auto name = cms_name(words[i++]);
    if (!name) throw AplError(ErrorKind::domain, reports::incorrect_parameter);
    for (double c : aplname(*name, "")) codes.push_back(c);
  }
  if (t.projection && i < words.size()) {
    const Choice* p = choose(projection_choices(), words[i++]);
    if (!p) throw AplError(ErrorKind::domain, reports::incorrect_parameter);
    codes.push_back(p->code);
    if (p->code == static_cast<int>(Projection::orthogonal) && i < words.size()) {
      const Choice* plane = choose(plane_choices(), words[i++]);
      if (!plane) throw AplError(ErrorKind::domain, reports::incorrect_parameter);
      codes.push_back(plane->code);
    }
  }
  if (!t.choices.empty() && i < words.size()) {
    const std::string w = upper(words[i++]);
    auto it = std::find_if(t.choices.begin(), t.choices.end(),
                           [&](const std::string& c) { return c.starts_with(w); });
    if (it == t.choices.end()) throw AplError(ErrorKind::domain, reports::incorrect_parameter);
    codes.push_back(static_cast<double>(it - t.choices.begin()) + 1);
  }
  for (; i < words.size(); ++i) {
    const auto x = parse_typed_number(words[i]);
    if (!x || !std::isfinite(*x)) throw AplError(ErrorKind::domain, reports::incorrect_parameter);
    codes.push_back(*x);
  }
  return codes;
}

// The words of a command's codes (COMCHA 1 is CHANGE GRID, COMDIS 5 3 3 30 DISPLAY SURFACE
// ISOMETRIC 3 30); the words themselves are then checked by the command as if typed.
std::vector<std::string> decode(const Command& command, std::span<const double> codes) {
  std::vector<std::string> words;
  std::size_t i = 0;
  auto whole = [&](double x, std::size_t count) {
    if (!(x >= 1 && x <= static_cast<double>(count)) || std::floor(x) != x)
      throw AplError(ErrorKind::domain);
    return static_cast<std::size_t>(x) - 1;
  };
  std::string_view follows = command.follows;
  if (!command.options.empty() && !codes.empty()) {
    const Choice& option = command.options[whole(codes[i++], command.options.size())];
    words.emplace_back(option.word);
    follows = option.follows;
  }
  const Takes t = takes(follows);
  if (t.name && i < codes.size()) {
    if (codes.size() - i < 5) throw AplError(ErrorKind::length);
    words.push_back(from_aplname(codes.subspan(i, 5)).first);
    i += 5;
  }
  if (t.projection && i < codes.size()) {
    const auto p = static_cast<Projection>(whole(codes[i++], 4) + 1);
    words.emplace_back(projection_word(p));
    if (p == Projection::orthogonal && i < codes.size()) {
      const std::string_view plane = plane_word(codes[i++]);
      if (plane == "?") throw AplError(ErrorKind::domain);
      words.emplace_back(plane);
    }
  }
  if (!t.choices.empty() && i < codes.size())
    words.push_back(t.choices[whole(codes[i++], t.choices.size())]);
  for (; i < codes.size(); ++i) words.push_back(format_typed_number(codes[i]));
  return words;
}

// --- the 4013's graph addresses ---------------------------------------------------------------

constexpr int screen_width = 1024, screen_height = 780;

// A picture of points in the 4013's addresses: its corners go with it (as points that draw
// nothing), so that the picture is the whole screen scaled to the picture's place.
Picture screen_picture() {
  Picture p;
  for (Point2 corner : {Point2{0, 0}, Point2{screen_width - 1, screen_height - 1}}) {
    const double xy[2] = {corner.x, corner.y};
    p.drawing.add_polyline(Point2View(xy, 1));
  }
  return p;
}

std::vector<Point2> screen_points(Args v) {
  const std::string bytes = text_of(v);
  if (bytes.size() % 4 != 0) throw AplError(ErrorKind::length);
  std::vector<Point2> points;
  for (std::size_t i = 0; i < bytes.size(); i += 4) {
    const auto p = tek_address_point(std::string_view(bytes).substr(i, 4));
    if (!p) throw AplError(ErrorKind::domain);
    points.push_back({static_cast<double>(p->x), static_cast<double>(p->y)});
  }
  return points;
}

Point2View view_of(const std::vector<Point2>& points, std::size_t first, std::size_t count) {
  return Point2View(&points[first].x, count, 2);
}

std::vector<Point2> rows_of(const Array& m) {
  std::vector<Point2> points;
  for (std::size_t r = 0; r < m.shape[0]; ++r)
    points.push_back({m.ravel[2 * r], m.ravel[2 * r + 1]});
  return points;
}

// Segments between each pair of points (TEKG, PLOTG), the points alone (TEKP, PLOTP), or one
// polyline through all (TEKV, PLOTV).
enum class Strokes { pairs, points, polyline };
void add_strokes(Drawing2& d, const std::vector<Point2>& points, Strokes how) {
  switch (how) {
    case Strokes::pairs:
      for (std::size_t i = 0; i + 1 < points.size(); i += 2) d.add_polyline(view_of(points, i, 2));
      return;
    case Strokes::points:
      for (const Point2& p : points) d.add_mark(p, MarkShape::dot, 1);
      return;
    case Strokes::polyline:
      if (!points.empty()) d.add_polyline(view_of(points, 0, points.size()));
      return;
  }
}

// --- WRT's card images ---------------------------------------------------------------------

// One value in a field of `width` (FORTRAN's I, F and E), asterisks when it does not fit.
std::string field(double x, int kind, int width, int decimals) {
  std::string t;
  if (kind == 1) t = fmt::format("{}", static_cast<long long>(std::llround(x)));
  if (kind == 3) t = fmt::format("{:.{}f}", x, decimals);
  if (kind == 4) t = fmt::format("{:.{}E}", x, decimals);
  if (static_cast<int>(t.size()) > width) return std::string(static_cast<std::size_t>(width), '*');
  return std::string(static_cast<std::size_t>(width) - t.size(), ' ') + t;
}

// The types WRT may write: any but igds's own binary files and its session's.
bool writable_type(std::string_view type) {
  for (std::string_view own : {"IGDSDATA", "IGDSIMAG", "IGDSCONT", "IGDSVARS", "IGDSVIMG",
                               "IGDSLOCK", "IGDSHIST", "IGDSBAD", "IGDSTEMP", "IGDSAPL"})
    if (type == own) return false;
  return !type.empty();
}

}  // namespace

void AplEnvironment::define_manual_functions() {
  define_line_functions();
  define_disk_functions();
  define_device_functions();
  define_dialogue_functions();
}

// FIT COONS and the functions they are made of: F0 F1 G0 G1 DISTA CURVILINEO COEFFICIENTI NOTO;
// the projections ORTHOG ISOM ASSON PROSPAR CONIC and SCALE.
void AplEnvironment::define_line_functions() {
  auto surface_input = [this] {
    if (ws_.nocur == 0) throw AplError(ErrorKind::value);
    return igds::surface_input(ws_);
  };
  session_.define_native(
      "FIT", 0,
      [this, surface_input](Args, Args) -> std::optional<Value> {
        Array made;
        const Array& patches = patches_of(ws_, made);
        if (patches.empty()) throw AplError(ErrorKind::value);
        try {
          return apl::to_value(refit(surface_input(), patches));
        } catch (const DataError& e) {
          refuse(e);
        }
      },
      "FIT: the grid INTPN from NOCUR NOSTR INTCU INTST INPPN PATCHES (the result)");
  session_.define_native(
      "COONS", 0,
      [this, surface_input](Args, Args) -> std::optional<Value> {
        try {
          session_.assign("PATCHES", apl::to_value(surface_patches(surface_input())));
        } catch (const DataError& e) {
          refuse(e);
        }
        return std::nullopt;
      },
      "COONS: PATCHES from NOCUR NOSTR INPPN INPTG");
  // The blending functions of the patches (docs/kernels.md), of each number of the argument.
  const std::pair<const char*, double Hermite::*> blends[] = {
      {"F0", &Hermite::f0}, {"F1", &Hermite::f1}, {"G0", &Hermite::g0}, {"G1", &Hermite::g1}};
  for (const auto& blend : blends) {
    const char* name = blend.first;
    double Hermite::*member = blend.second;
    session_.define_native(
        name, 1,
        [member](Args, Args s) -> std::optional<Value> {
          if (!s || s->is_character()) throw AplError(ErrorKind::domain);
          Value r = *s;
          for (double& x : r.mutable_numbers()) x = hermite(x).*member;
          return r;
        },
        fmt::format("{} S: the blending function {} at each S", name, name));
  }
  session_.define_native(
      "DISTA", 1,
      [](Args, Args p) -> std::optional<Value> {
        const Array m = matrix_of(p, 3);
        const Vec3View points = as_vec3(m);
        std::vector<double> d;
        for (std::size_t k = 0; k + 1 < points.size(); ++k)
          d.push_back(chord_length(points[k], points[k + 1]));
        return numbers_value(std::move(d));
      },
      "DISTA P: the distances from each point of P (rows x y z) to the next");
  // CURVILINEO, COEFFICIENTI and NOTO work on the grid line COONS gave them in 1975: here the
  // points PUNTI (rows x y z) and the end tangents TANGENTI (2 rows), as the caller sets them.
  auto line = [this] {
    auto points = session_.variable("PUNTI");
    auto tangents = session_.variable("TANGENTI");
    if (!points || !tangents) throw AplError(ErrorKind::value);
    Array p = matrix_of(&*points, 3), t = matrix_of(&*tangents, 3);
    if (t.shape[0] != 2 || p.shape[0] < 2) throw AplError(ErrorKind::length);
    return std::pair{std::move(p), std::move(t)};
  };
  session_.define_native(
      "CURVILINEO", 0,
      [line](Args, Args) -> std::optional<Value> {
        const auto [p, t] = line();
        const Vec3View points = as_vec3(p), ends = as_vec3(t);
        std::vector<Vec3> tangents(points.size());
        spline_tangents(points, ends[0], ends[1], tangents);
        const std::size_t n = points.size();
        Array r;
        r.shape = {n, 7};
        for (std::size_t k = 0; k < n; ++k) {
          const Vec3 q = points[k], g = tangents[k];
          const double to_next = k + 1 < n ? chord_length(q, points[k + 1]) : 0;
          r.ravel.insert(r.ravel.end(), {to_next, q.x, q.y, q.z, g.x, g.y, g.z});
        }
        for (double x : r.ravel)
          if (!std::isfinite(x)) throw AplError(ErrorKind::domain);
        return apl::to_value(r);
      },
      "CURVILINEO: the spline through PUNTI with end tangents TANGENTI: each row the distance "
      "to the next point, the point, its tangent");
  // The system's rows: the end tangents are known (rows 1 and N), the others spline_row's.
  auto rows = [](const Array& p) {
    const Vec3View q = as_vec3(p);
    std::vector<SplineRow> out;
    for (std::size_t i = 1; i + 1 < q.size(); ++i)
      out.push_back(spline_row(q[i] - q[i - 1], q[i + 1] - q[i], chord_length(q[i - 1], q[i]),
                               chord_length(q[i], q[i + 1])));
    return out;
  };
  session_.define_native(
      "COEFFICIENTI", 0,
      [line, rows](Args, Args) -> std::optional<Value> {
        const auto [p, t] = line();
        const std::size_t n = p.shape[0];
        Array m;
        m.shape = {n, n};
        m.ravel.assign(n * n, 0.0);
        m.ravel[0] = 1;
        m.ravel[n * n - 1] = 1;
        const auto r = rows(p);
        for (std::size_t i = 1; i + 1 < n; ++i) {
          const SplineRow& row = r[i - 1];
          m.ravel[i * n + i - 1] = row.lower;
          m.ravel[i * n + i] = row.diagonal;
          m.ravel[i * n + i + 1] = row.upper;
        }
        for (double x : m.ravel)
          if (!std::isfinite(x)) throw AplError(ErrorKind::domain);
        return apl::to_value(m);
      },
      "COEFFICIENTI: the matrix of the tangents' system for PUNTI (rows 1 and N: the ends)");
  session_.define_native(
      "NOTO", 1,
      [line, rows](Args, Args k) -> std::optional<Value> {
        const int c = whole_of(k, 1, 3) - 1;
        const auto [p, t] = line();
        const Vec3View ends = as_vec3(t);
        auto pick = [c](Vec3 v) { return c == 0 ? v.x : c == 1 ? v.y : v.z; };
        std::vector<double> known{pick(ends[0])};
        for (const SplineRow& row : rows(p)) known.push_back(pick(row.known));
        known.push_back(pick(ends[1]));
        for (double x : known)
          if (!std::isfinite(x)) throw AplError(ErrorKind::domain);
        return numbers_value(std::move(known));
      },
      "NOTO K: the known terms of the tangents' system for PUNTI, component K (1 X, 2 Y, 3 Z)");
  session_.define_native(
      "ORTHOG", 2,
      [](Args points, Args dropped) -> std::optional<Value> {
        const int d = whole_of(dropped, 1, 3);
        const int plane = d == 3 ? 1 : d == 2 ? 2 : 3;  // the plane of the other two coordinates
        return projected(points_of(points, 3),
                         [&](Vec3View in, MutablePoint2View out) { orthog(in, plane, out); });
      },
      "P ORTHOG K: the points P (last axis 3) without their coordinate K (1 X, 2 Y, 3 Z)");
  session_.define_native(
      "ISOM", 2,
      [](Args points, Args parameters) -> std::optional<Value> {
        const auto p = numbers_of(parameters, 2);
        if (p[0] != 1 && p[0] != 2 && p[0] != 3) throw AplError(ErrorKind::domain);
        return projected(points_of(points, 3), [&](Vec3View in, MutablePoint2View out) {
          isom(in, static_cast<int>(p[0]), p[1], out);
        });
      },
      "P ISOM AXIS ANGLE: the isometric projection of the points P");
  session_.define_native(
      "ASSON", 2,
      [](Args points, Args angles) -> std::optional<Value> {
        const auto a = numbers_of(angles, 3);
        return projected(points_of(points, 3), [&](Vec3View in, MutablePoint2View out) {
          asson(in, {a[0], a[1], a[2]}, out);
        });
      },
      "P ASSON A B C: the axonometric projection of the points P, angles in degrees");
  session_.define_native(
      "PROSPAR", 2,
      [](Args points, Args angles) -> std::optional<Value> {
        const auto a = numbers_of(angles, 2);
        return projected(points_of(points, 3), [&](Vec3View in, MutablePoint2View out) {
          prospar(in, {a[0], a[1]}, out);
        });
      },
      "P PROSPAR A1 A2: the parallel projection of the points P that ASSON makes of its scaled "
      "points");
  session_.define_native(
      "CONIC", 2,
      [](Args points, Args view) -> std::optional<Value> {
        const auto v = numbers_of(view, 3);
        const Array p = points_of(points, 3);
        return projected(p, [&](Vec3View in, MutablePoint2View out) {
          conic(in, {v[0], v[1], v[2]}, bounding_box_centre(in), out);
        });
      },
      "P CONIC V: the perspective of the points P seen from V towards their centre");
  session_.define_native(
      "SCALE", 2,
      [](Args box, Args points) -> std::optional<Value> {
        // The points' bounding box into the rectangle from (X0, Y0) to (XMAX, YMAX), one scale
        // for both axes, from the corner (X0, Y0), as DISPLA scaled IMAGE for the screen.
        const auto b = numbers_of(box, 4);
        Array p = points_of(points, 2);
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (std::size_t i = 0; i < p.size(); ++i) {
          lo[i % 2] = std::min(lo[i % 2], p.ravel[i]);
          hi[i % 2] = std::max(hi[i % 2], p.ravel[i]);
        }
        const double w = hi[0] - lo[0], h = hi[1] - lo[1];
        const double sx = w > 0 ? (b[2] - b[0]) / w : INFINITY,
                     sy = h > 0 ? (b[3] - b[1]) / h : INFINITY;
        double s = std::min(sx, sy);
        if (!std::isfinite(s)) s = 1;
        for (std::size_t i = 0; i < p.size(); ++i)
          p.ravel[i] = b[i % 2] + s * (p.ravel[i] - lo[i % 2]);
        return apl::to_value(p);
      },
      "X0 Y0 XMAX YMAX SCALE P: the points P (last axis 2) scaled into that rectangle");
}

// The session and the disk: INIT AUTOMSAVE RESTORE DEFVAR STATE WRT APLNAME; DESCR and LUT.
void AplEnvironment::define_disk_functions() {
  session_.define_native(
      "DESCR", 1,
      [](Args, Args d) -> std::optional<Value> {
        const auto v = numbers_of(d, 5);
        Image image;
        image.desim = description_of(v);
        if (image_problem(image)) throw AplError(ErrorKind::domain);
        return Value::text(describe_line(image.desim));
      },
      "DESCR DESIM: the description of an image, as DISPLAY writes it");
  session_.define_native(
      "LUT", 2,
      [](Args table, Args word) -> std::optional<Value> {
        // The first row of the character matrix that starts with the word (its row number,
        // from 1), else 0: how GETCOM looked commands up in their table.
        if (!table || !word || !table->is_character() || !word->is_character())
          throw AplError(ErrorKind::domain);
        if (table->rank() != 2 || word->rank() > 1) throw AplError(ErrorKind::rank);
        const auto t = table->characters();
        const auto w = word->characters();
        const std::size_t rows = table->shape()[0], cols = table->shape()[1];
        for (std::size_t r = 0; r < rows; ++r)
          if (w.size() <= cols && std::equal(w.begin(), w.end(), t.begin() + r * cols))
            return Value::number(static_cast<double>(r + 1));
        return Value::number(0);
      },
      "TABLE LUT WORD: the first row of TABLE that starts with WORD, else 0");
  session_.define_native(
      "INIT", 0,
      [this](Args, Args) -> std::optional<Value> {
        hooks_.say("INIT: THE SESSION WAS RESTORED WHEN IGDS STARTED; RESTORE READS IT AGAIN");
        return std::nullopt;
      },
      "INIT: done by igds when it starts (the session comes back by itself)");
  session_.define_native(
      "AUTOMSAVE", 0,
      [this](Args, Args) -> std::optional<Value> {
        if (auto problem = start())
          throw AplError(ErrorKind::domain, fmt::format("CANNOT START: {}", *problem));
        const std::string failed = hooks_.save_session();
        if (!failed.empty()) throw AplError(ErrorKind::domain, failed);
        return std::nullopt;
      },
      "AUTOMSAVE: the session saved on the disk now (BINSAVE.IGDSCONT)");
  session_.define_native(
      "RESTORE", 0,
      [this](Args, Args) -> std::optional<Value> {
        std::optional<Workspace> loaded = hooks_.load_session();
        if (!loaded) throw AplError(ErrorKind::domain, "THE SESSION ON THE DISK CANNOT BE READ");
        // The APL workspace's own stay.
        loaded->functions = ws_.functions;
        loaded->apl_variables = std::move(ws_.apl_variables);
        ws_ = std::move(*loaded);
        assigned_.clear();
        values_.clear();
        return std::nullopt;
      },
      "RESTORE: the IGDS variables as the session on the disk holds them");
  session_.define_native(
      "DEFVAR", 0,
      [this](Args, Args) -> std::optional<Value> {
        Workspace empty;
        empty.functions = std::move(ws_.functions);
        empty.apl_variables = std::move(ws_.apl_variables);
        ws_ = std::move(empty);
        assigned_.clear();
        values_.clear();
        return std::nullopt;
      },
      "DEFVAR: the IGDS variables of a very first session (no surface, no image)");
  session_.define_native(
      "STATE", 1,
      [this](Args, Args file) -> std::optional<Value> {
        const auto [name, type] = name_and_type(file);
        if (type.empty()) throw AplError(ErrorKind::length);
        return Value::number(hooks_.disk && hooks_.disk->exists(name, type) ? 1 : 0);
      },
      "STATE 'NAME TYPE': 1 when the file NAME.TYPE is on the disk, else 0");
  session_.define_native(
      "APLNAME", 1,
      [](Args, Args file) -> std::optional<Value> {
        const auto [name, type] = name_and_type(file);
        return numbers_value(aplname(name, type));
      },
      "APLNAME 'NAME TYPE': the five numbers that name a file for WRT and the COMxxx codes");
  session_.define_native(
      "WRT", 2,
      [this](Args control, Args data) -> std::optional<Value> {
        // V WRT M: V[1] 1 a new file, 0 records added; V[2] 1 integers, 2 characters, 3 fixed,
        // 4 exponent form; V[3 4 5] the field's width, its decimals, fields per record;
        // V[6 ... 10] the file's APLNAME.
        const auto v = numbers_of(control, 10);
        const auto [name, type] = from_aplname(std::span<const double>(v).subspan(5));
        if (!writable_type(type)) throw AplError(ErrorKind::domain);
        const int kind = static_cast<int>(v[1]), width = static_cast<int>(v[2]),
                  decimals = static_cast<int>(v[3]), per_record = static_cast<int>(v[4]);
        if ((v[0] != 0 && v[0] != 1) || kind < 1 || kind > 4 || width < 1 || width > 80 ||
            decimals < 0 || decimals > 30 || per_record < 1 || per_record * width > 80 ||
            std::floor(v[2]) != v[2] || std::floor(v[3]) != v[3] || std::floor(v[4]) != v[4])
          throw AplError(ErrorKind::domain);
        if (!data) throw AplError(ErrorKind::value);
        if (data->rank() > 2) throw AplError(ErrorKind::rank);
        std::string text;
        if (kind == 2) {
          if (!data->is_character()) throw AplError(ErrorKind::domain);
          const std::size_t cols = data->rank() == 0 ? 1 : data->shape().back();
          auto c = data->characters();
          for (std::size_t r = 0; cols > 0 && r < c.size() / cols; ++r) {
            std::string row = Value::text(std::u32string_view(c.data() + r * cols, cols)).utf8();
            row.erase(row.find_last_not_of(' ') + 1);
            text += row + "\n";
          }
        } else {
          if (data->is_character()) throw AplError(ErrorKind::domain);
          auto x = data->numbers();
          for (std::size_t i = 0; i < x.size(); ++i) {
            text += field(x[i], kind, width, decimals);
            if ((i + 1) % static_cast<std::size_t>(per_record) == 0 || i + 1 == x.size())
              text += "\n";
          }
        }
        if (!hooks_.disk) throw AplError(ErrorKind::domain, "NO DISK");
        try {
          if (v[0] == 0 && hooks_.disk->exists(name, type))
            text = read_user_file(*hooks_.disk, name, type, std::size_t{256} << 20,
                                  "NO FILE CHANGED") +
                   text;
          write_user_file(*hooks_.disk, name, type, text, true);
        } catch (const Report& r) {
          throw AplError(ErrorKind::domain, r.what());
        }
        return std::nullopt;
      },
      "V WRT M: M written in card images on the disk as V says (V[6 ... 10] the APLNAME)");
}

// The plotter and the screen: PLOTHP PLOTG PLOTP PLOTV DISPLA TKX TEKG TEKP TEKV TEKC OUT.
void AplEnvironment::define_device_functions() {
  session_.define_native(
      "PLOTHP", 0,
      [this](Args, Args) -> std::optional<Value> {
        // The keyboard of the last PLOT (STATUS[2], PLOT's option codes), else the first.
        const Choice* keyboard = &plot_command.options.front();
        for (const Choice& o : plot_command.options)
          if (o.code == ws_.status[1]) keyboard = &o;
        run_command({std::string(plot_command.name), std::string(keyboard->word)});
        return std::nullopt;
      },
      "PLOTHP: IMAGE on the plotter, as PLOT draws it");
  const std::tuple<const char*, const char*, Strokes> strokes[] = {
      {"PLOTG", "TEKG", Strokes::pairs},
      {"PLOTP", "TEKP", Strokes::points},
      {"PLOTV", "TEKV", Strokes::polyline}};
  const char* what[] = {"a segment between each pair of rows", "a point for each row",
                        "a line through the rows in order"};
  for (const auto& [plot_name, tek_name, how] : strokes) {
    const char* meaning = what[static_cast<int>(how)];
    session_.define_native(
        plot_name, 1,
        [this, how = how](Args, Args m) -> std::optional<Value> {
          Picture p;
          add_strokes(p.drawing, rows_of(matrix_of(m, 2)), how);
          if (p.drawing.empty()) throw AplError(ErrorKind::length);
          hooks_.plot(p);
          return std::nullopt;
        },
        fmt::format("{} M: a plot of {} of M (x y)", plot_name, meaning));
    session_.define_native(
        tek_name, 1,
        [this, how = how, tek_name = tek_name](Args, Args s) -> std::optional<Value> {
          Picture p = screen_picture();
          add_strokes(p.drawing, screen_points(s), how);
          hooks_.draw(p, fmt::format("IMAGE: {}", tek_name));
          return std::nullopt;
        },
        fmt::format("{} S: on the screen, {} of S (4013 addresses, as TKX makes them)", tek_name,
                    meaning));
  }
  session_.define_native(
      "TKX", 1,
      [](Args, Args m) -> std::optional<Value> {
        const Array a = matrix_of(m, 2);
        std::string bytes;
        for (std::size_t r = 0; r < a.shape[0]; ++r) {
          const double x = a.ravel[2 * r], y = a.ravel[2 * r + 1];
          if (!(x >= 0 && x < screen_width && y >= 0 && y < screen_height))
            throw AplError(ErrorKind::domain);
          bytes += tek_address(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)));
        }
        return Value::text(bytes);
      },
      "TKX M: the 4013's addresses of the screen points M (x 0-1023, y 0-779)");
  session_.define_native(
      "TEKC", 2,
      [this](Args text, Args at) -> std::optional<Value> {
        const auto p = numbers_of(at, 2);
        if (!(p[0] >= 0 && p[0] < screen_width && p[1] >= 0 && p[1] < screen_height))
          throw AplError(ErrorKind::domain);
        Picture picture = screen_picture();
        picture.drawing.add_text(Point2{p[0], p[1]}, text_of(text));
        hooks_.draw(picture, "IMAGE: TEKC");
        return std::nullopt;
      },
      "'TEXT' TEKC X Y: the text on the screen from the point X Y");
  session_.define_native(
      "OUT", 1,
      [this](Args, Args text) -> std::optional<Value> {
        hooks_.say(text_of(text));
        return std::nullopt;
      },
      "OUT 'TEXT': the text as a line of the dialogue");
  session_.define_native(
      "DISPLA", 0,
      [this](Args, Args) -> std::optional<Value> {
        if (auto problem = start())
          throw AplError(ErrorKind::domain, fmt::format("CANNOT START: {}", *problem));
        if (!ws_.image) throw AplError(ErrorKind::domain, reports::image_not_found);
        hooks_.show(ws_.image);
        return std::nullopt;
      },
      "DISPLA: IMAGE on the screen with its description, as DISPLAY shows it");
}

std::vector<double> AplEnvironment::codes_of(const Command& command,
                                             std::vector<std::string> words) {
  // The option is asked when it is not there, as the command asks it.
  if (words.empty() && !command.options.empty() && !command.option_prompt.text.empty()) {
    hooks_.say(command.option_prompt.text);
    words = split_words(read_answer(command_number(command)));
  }
  return encode(command, words);
}

std::string AplEnvironment::read_answer(int code) {
  for (;;) {
    std::optional<std::string> line = hooks_.read("");
    if (!line) throw AplError(ErrorKind::interrupt);
    std::vector<std::string_view> words;
    split_words(*line, words);
    const HelpRequest help = help_request(words);
    if (!help.asked) return *line;
    if (help.length >= 0) ws_.status[0] = help.length;
    values_.erase("STATUS");
    explain(code, ws_.status[0] == 1);
  }
}

void AplEnvironment::explain(int code, bool long_text) {
  const auto table = command_table();
  if (code < 0 || code > static_cast<int>(table.size())) throw AplError(ErrorKind::domain);
  if (code == 0) {
    if (long_text) {
      hooks_.document(help_overview());
    } else {
      std::string names;
      for (const Command* c : table) names += fmt::format(" {}", c->name);
      hooks_.say(fmt::format("COMMANDS:{}", names));
    }
    return;
  }
  const Command& c = *table[static_cast<std::size_t>(code - 1)];
  if (long_text)
    hooks_.document(c.long_help);
  else
    hooks_.say(fmt::format("{}: {}", c.name, c.summary));
}

// The dialogue of IGDS4013 and its command functions: ALFINP NUMINP EXPL EXPLONG GETCOM, the
// PARxx, the COMxxx, CHGRID CHPOINT CHTANG.
void AplEnvironment::define_dialogue_functions() {
  const int commands = static_cast<int>(command_table().size());
  session_.define_native(
      "ALFINP", 1,
      [this, commands](Args, Args code) -> std::optional<Value> {
        return Value::text(read_answer(whole_of(code, 0, commands)));
      },
      "ALFINP C: a line typed (HELP there explains command C, 0 IGDS)");
  session_.define_native(
      "NUMINP", 1,
      [this, commands](Args, Args code) -> std::optional<Value> {
        const int c = whole_of(code, 0, commands);
        for (;;) {
          std::vector<double> numbers;
          bool good = true;
          for (const auto& w : split_words(read_answer(c))) {
            const auto x = parse_typed_number(w);
            good = good && x && std::isfinite(*x);
            if (good) numbers.push_back(*x);
          }
          if (good) return numbers_value(std::move(numbers));
          hooks_.report(reports::incorrect_entry);
        }
      },
      "NUMINP C: the numbers of a line typed (HELP there explains command C)");
  session_.define_native(
      "EXPL", 1,
      [this, commands](Args, Args code) -> std::optional<Value> {
        explain(whole_of(code, 0, commands), ws_.status[0] == 1);
        return std::nullopt;
      },
      "EXPL C: the explanation of command C (0 IGDS) in the length of STATUS[1]");
  session_.define_native(
      "EXPLONG", 1,
      [this, commands](Args, Args code) -> std::optional<Value> {
        explain(whole_of(code, 0, commands), true);
        return std::nullopt;
      },
      "EXPLONG C: the long explanation of command C (0 IGDS)");
  session_.define_native(
      "GETCOM", 0,
      [this](Args, Args) -> std::optional<Value> {
        const std::vector<std::string> words = split_words(read_answer(0));
        const Command* c = words.empty() ? nullptr : find_command(words[0]);
        if (!c) {
          hooks_.report(reports::incorrect_command);
          return Value::number(0);
        }
        try {
          std::vector<double> codes{static_cast<double>(command_number(*c))};
          for (double x : codes_of(*c, {words.begin() + 1, words.end()})) codes.push_back(x);
          return numbers_value(std::move(codes));
        } catch (const AplError& e) {
          hooks_.report(e.what());
          return Value::number(0);
        }
      },
      "GETCOM: a command typed, as numbers: the command's number, then its codes (0: none)");
  for (const Command* c : manual_commands()) {
    const std::string word(c->name);
    const std::string parse = "PAR" + word.substr(0, 2);
    session_.define_native(
        parse, 1,
        [this, c](Args, Args rest) -> std::optional<Value> {
          return numbers_value(codes_of(*c, words_of(rest)));
        },
        fmt::format("{} 'WORDS': the codes of what follows {} (as GETCOM gives them)", parse,
                    word));
    const std::string function = "COM" + word.substr(0, 3);
    const bool end = c == &end_command;
    session_.define_native(
        function, 1,
        [this, c, end](Args, Args argument) -> std::optional<Value> {
          std::vector<std::string> line{std::string(c->name)};
          const std::vector<std::string> rest = argument && argument->is_numeric()
                                                    ? decode(*c, number_list(argument))
                                                    : words_of(argument);
          line.insert(line.end(), rest.begin(), rest.end());
          if (end) {
            // Already in APL: END APL stays, END CMS leaves igds.
            const Choice* option = line.size() > 1 ? choose(c->options, line[1]) : nullptr;
            if (!option) throw AplError(ErrorKind::domain, reports::incorrect_choice);
            if (option != &c->options.front()) session_.request(apl::AplSession::Next::off);
            return std::nullopt;
          }
          run_command(std::move(line));
          return std::nullopt;
        },
        fmt::format("{} 'WORDS' or {} CODES: the command {} with those words (or GETCOM's "
                    "codes)",
                    function, function, word));
  }
  // CHANGE's first three options, in the order of its declaration (the manual's GRID,
  // TANGENTS, POINTS).
  const char* changes[] = {"CHGRID", "CHTANG", "CHPOINT"};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::string option(change_command.options[k].word);
    session_.define_native(
        changes[k], 1,
        [this, option](Args, Args) -> std::optional<Value> {
          run_command({std::string(change_command.name), option});
          return std::nullopt;
        },
        fmt::format("{} C: {} {}, its questions asked (C, the caller, is not used)", changes[k],
                    change_command.name, option));
  }
}

}  // namespace igds
