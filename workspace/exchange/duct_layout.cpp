// A drawing laid out as a DUCT picture (docs/exchange.md, "Writing"): its instructions,
// counters, limits and pixels.
#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "workspace/drawing/flatten.h"
#include "workspace/drawing/project.h"
#include "workspace/exchange/duct_parts.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/parallel.h"
#include "workspace/numbers/fortran.h"

namespace igds {

namespace duct {

namespace {

bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A coordinate as a reader gets it from its pixel line: E14.7's seven digits.
double as_written(double v) {
  char field[40];
  const char* end = fortran::put_e_whole(field, v, 14, 7);
  return fortran::read_real(trimmed({field, std::size_t(end - field)})).value_or(v);
}

Vec3 as_written(Vec3 v) {
  return {as_written(v.x), as_written(v.y), as_written(v.z)};
}

// A shape factor as a reader gets it from its T field.
double as_written_shape(double s) {
  char field[10];
  if (!fortran::put_f_input(field, s, 10, 4)) return s;
  return fortran::read_f({field, 10}, 0, 10, 4).value_or(s);
}

struct Box {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  void add(Vec3 p) {
    if (!finite(p)) return;  // an extreme evaluated inside a span of huge numbers
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  bool empty() const { return lo.x > hi.x; }
};

// Whether a curve's weights make it rational (an empty list is all ones).
bool is_rational(std::span<const double> w) {
  return !w.empty() && std::any_of(w.begin(), w.end(), [&](double x) { return x != w[0]; });
}

// The tight box of what a reader draws from the file (docs/exchange.md, "Limits"): pixels on the
// curves, and the extremes inside each span, both from the coordinates as written. Rounding to
// E14.7 never reorders values, so of the pixels only the extremes are rounded, at the end; a
// written coordinate is within 5e-7 of its magnitude of the exact one.
class BoxBuilder {
 public:
  // A pixel on what is drawn.
  void add(Vec3 p) {
    pixels_.add(p);
    stale_ = true;
  }
  // Pixels boxed elsewhere.
  void add(const Box& pixels) {
    if (pixels.empty()) return;
    add(pixels.lo);
    add(pixels.hi);
  }
  // A Bézier span, once every pixel is in: its inside is the span of the written controls,
  // worked out only when the span could reach past the box (near a flat end the written span can
  // pass its end pixel).
  void add_bezier(const Vec3 (&controls)[4]) {
    settle();
    if (held(controls)) return;  // the span lies in its controls' hull
    const Vec3 margin = rounding(controls);
    Vec3 extremes[8];
    std::size_t n = span_extremes(3, controls, {}, extremes);
    extremes[n++] = controls[0];
    extremes[n++] = controls[3];
    if (std::all_of(extremes, extremes + n,
                    [&](Vec3 p) { return inside(p - margin) && inside(p + margin); }))
      return;
    Vec3 written[4];
    for (std::size_t k = 0; k < 4; ++k) written[k] = as_written(controls[k]);
    const std::size_t m = span_extremes(3, written, {}, extremes);
    for (std::size_t k = 0; k < m; ++k) inner_.add(extremes[k]);
    stale_ = true;
  }
  // Whether the controls of a Bézier span lie inside what is known of the box by more than their
  // rounding, and so does the span of its written controls: such a span adds nothing. What is
  // known only grows, so a span held now is held later. After settle().
  bool held(const Vec3 (&controls)[4]) const {
    // Every control less and plus its margin inside: the least and the greatest decide, as
    // rounding keeps the order of values (and a control less its margin is below it plus it).
    const Vec3 margin = rounding(controls);
    Vec3 least = controls[0], most = controls[0];
    for (Vec3 c : controls) {
      least = {std::min(least.x, c.x), std::min(least.y, c.y), std::min(least.z, c.z)};
      most = {std::max(most.x, c.x), std::max(most.y, c.y), std::max(most.z, c.z)};
    }
    const Vec3 low = least - margin, high = most + margin;
    return low.x >= lo_.x && low.y >= lo_.y && low.z >= lo_.z && high.x <= hi_.x &&
           high.y <= hi_.y && high.z <= hi_.z;
  }
  // A conic span P0 M P1 with shape factor s, drawn as read_duct's reader draws it from the
  // written numbers.
  void add_conic(Vec3 p0, Vec3 mid, Vec3 p1, double shape) {
    add(p0);
    add(mid);
    add(p1);
    const ConicSpans spans =
        conic_spans(as_written(p0), as_written(mid), as_written(p1), as_written_shape(shape));
    Vec3 extremes[6];
    for (int k = 0; k < spans.spans; ++k) {
      const std::span<const Vec3> c(&spans.controls[std::size_t(2 * k)], 3);
      const std::span<const double> w(&spans.weights[std::size_t(2 * k)], 3);
      const std::size_t n = span_extremes(2, c, w, extremes);
      for (std::size_t e = 0; e < n; ++e) inner_.add(extremes[e]);
      inner_.add(c[2]);  // a split span's middle end
    }
  }
  bool empty() const { return pixels_.empty(); }
  // The sides of what is known of the box worked out, for held(), once pixels or spans were
  // added.
  void settle() {
    if (stale_) find_sides();
  }
  // The box of both: the extreme pixels as written.
  Box box() const {
    Box b = inner_;
    b.add(as_written(pixels_.lo));
    b.add(as_written(pixels_.hi));
    return b;
  }

 private:
  // The sides of what is known of the box: the pixels' box less their rounding, or the written
  // spans' extremes beyond it. Worked out again only when either has grown.
  void find_sides() {
    auto low = [](double pixel, double inner) {
      return std::min(pixel + 5e-7 * std::abs(pixel), inner);
    };
    auto high = [](double pixel, double inner) {
      return std::max(pixel - 5e-7 * std::abs(pixel), inner);
    };
    const Box& b = pixels_;
    const Box& i = inner_;
    lo_ = {low(b.lo.x, i.lo.x), low(b.lo.y, i.lo.y), low(b.lo.z, i.lo.z)};
    hi_ = {high(b.hi.x, i.hi.x), high(b.hi.y, i.hi.y), high(b.hi.z, i.hi.z)};
    stale_ = false;
  }
  // How far the written controls of a span can be from the exact ones, along each axis.
  static Vec3 rounding(const Vec3 (&controls)[4]) {
    Vec3 most{0, 0, 0};
    for (Vec3 c : controls)
      most = {std::max(most.x, std::abs(c.x)), std::max(most.y, std::abs(c.y)),
              std::max(most.z, std::abs(c.z))};
    return 5e-7 * most;
  }
  // Whether `p` is inside what is known of the box.
  bool inside(Vec3 p) const {
    return p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y && p.z >= lo_.z &&
           p.z <= hi_.z;
  }
  Box pixels_, inner_;
  Vec3 lo_, hi_;  // find_sides()
  bool stale_ = true;
};

DuctMark duct_mark(MarkShape shape) {
  switch (shape) {
    case MarkShape::cross:
      return DuctMark::cross;
    case MarkShape::square:
      return DuctMark::square;
    case MarkShape::diamond:
    case MarkShape::circle:
      return DuctMark::diamond;
    case MarkShape::plus:
    case MarkShape::dot:
      break;
  }
  return DuctMark::plus;
}

DuctDash duct_dash(Dash dash) {
  switch (dash) {
    case Dash::solid:
      return DuctDash::solid;
    case Dash::chain:
      return DuctDash::chain;
    case Dash::dashed:
    case Dash::dotted:
      break;
  }
  return DuctDash::dashed;
}

// Printable ASCII for a line of the file: control and other bytes become '?'.
std::string printable(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (!(c >= 0x20 && c < 0x7F)) c = '?';
  return out;
}

// A limit rounded outwards to a value that F10.4's columns hold exactly (docs/exchange.md,
// "Limits"): on F10.4's grid of 1e-4 from a magnitude of 1 while it fits (five digits and more);
// else to the most significant digits fortran::input_text fits in 10 columns.
double outwards(double v, bool up) {
  if (v == 0 || !std::isfinite(v)) return v;
  // A value on the grid but for the rounding of a span's evaluation stays there.
  const double slack = 1e-13 * std::abs(v);
  auto outside = [&](double r) { return up ? r >= v - slack : r <= v + slack; };
  const double towards = up ? 1 : -1;
  if (std::abs(v) >= 1) {
    auto on_grid = [](double x) -> std::optional<double> {
      char field[10];
      if (!fortran::put_f(field, x, 10, 4)) return std::nullopt;
      return fortran::read_f({field, 10}, 0, 10, 4);
    };
    std::optional<double> r = on_grid(v);
    if (r && !outside(*r)) r = on_grid(*r + towards * 0.6e-4);
    if (r && outside(*r) && std::abs(*r) >= 1) return *r;
  }
  auto in_columns = [](double x) {
    for (int digits = 17;; --digits)
      if (const std::string t = fortran::input_text(x, digits); t.size() <= 10 || digits == 1)
        return fortran::read_real(t).value_or(x);
  };
  double r = in_columns(v);
  // One step of the grid outwards: the smallest move that rounds elsewhere (steps grow by half,
  // so the first that moves is under 3/4 of the grid's step and lands on the next value).
  for (double move = 1e-8 * std::abs(r); !outside(r); move *= 1.5) {
    const double next = in_columns(r + towards * move);
    if (next != r) r = next;
  }
  return r;
}

// The largest extent of every point of a drawing (0 when it has none).
template <class P>
double extent_of(const Drawing<P>& drawing) {
  const Box3 all = bounding_box(drawing);
  return all.lo.x <= all.hi.x
             ? std::max({all.hi.x - all.lo.x, all.hi.y - all.lo.y, all.hi.z - all.lo.z})
             : 0.0;
}

// Whether every point and weight of an item is finite (and every weight positive).
template <class P>
bool finite_item(const Drawing<P>& drawing, const typename Drawing<P>::Item& item) {
  const auto points = drawing.points(item);
  bool finite = true;
  // Every coordinate, without a branch per point: a number is finite when its exponent bits
  // are not all ones.
  constexpr std::uint64_t exponent = 0x7FF0000000000000;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double* d = points.data() + points.stride() * k;
    for (std::size_t c = 0; c < P::dimension; ++c)
      finite &= (std::bit_cast<std::uint64_t>(d[c]) & exponent) != exponent;
  }
  const auto w = drawing.weights(item);
  return finite &&
         std::all_of(w.begin(), w.end(), [](double x) { return std::isfinite(x) && x > 0; });
}

// A Bézier span of a drawing's polynomial cubic: controls k .. k + 3.
template <class P>
void load_span(typename Drawing<P>::View points, std::size_t k, Vec3 (&span)[4]) {
  for (std::size_t c = 0; c < 4; ++c) span[c] = in_space(P(points[k + c]));
}

// The items of a drawing cut into one part per core (parallel.h) of about as many points each:
// part t is items [cuts[t], cuts[t + 1]).
template <class P>
std::vector<std::size_t> item_parts(const Drawing<P>& drawing) {
  const auto items = drawing.items();
  std::size_t total = 0;
  for (const auto& item : items) total += item.count;
  const unsigned parts = threads_for(P::dimension * total);
  std::vector<std::size_t> cuts(parts + 1, items.size());
  cuts[0] = 0;
  std::size_t before = 0;  // the points of the items before item n
  unsigned t = 1;
  for (std::size_t n = 0; n < items.size() && t < parts; ++n) {
    while (t < parts && before * parts >= total * t) cuts[t++] = n;
    before += items[n].count;
  }
  return cuts;
}

}  // namespace

template <class P>
Layout lay_out(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view) {
  using Kind = typename Drawing<P>::Kind;
  Layout laid{{}, PixelRuns(P::dimension)};
  DuctPicture& p = laid.picture;
  PixelRuns& pixels = laid.pixels;
  std::string first = printable(fmt::format("IGDS PICTURE FILE {} {}", header.name, header.date));
  p.header.push_back(first);
  if (!header.title.empty()) {
    std::string title = printable(header.title);
    if (trimmed(title) == "*") title = "(*)";
    p.header.push_back(title);
  }

  const auto items = drawing.items();
  const auto is_bezier = [&](const typename Drawing<P>::Item& item) {
    return item.kind == Kind::curve && item.degree == 3 && !is_rational(drawing.weights(item));
  };
  // The two walks over every point (checked and boxed, then the Bézier spans near the box's
  // sides found) run on every core, each on a part of the items; what they find is the same
  // however the items are cut.
  const std::vector<std::size_t> cuts = item_parts(drawing);
  const auto parts = unsigned(cuts.size() - 1);

  // Every point is checked before anything is laid out (the first item that is not finite is
  // refused), and the pixels on what is drawn among the drawing's points are boxed (the conic
  // arcs' and the flattened rational cubics', made below, as they are made).
  constexpr std::size_t none = std::size_t(-1);
  std::vector<Box> boxes(parts);
  std::vector<std::size_t> refused(parts, none);
  in_parallel(parts, [&](unsigned t) {
    for (std::size_t n = cuts[t]; n < cuts[t + 1]; ++n) {
      const auto& item = items[n];
      if (!finite_item(drawing, item)) {
        refused[t] = n;
        return;
      }
      const auto points = drawing.points(item);
      if (item.kind != Kind::curve) {
        for (P point : points) boxes[t].add(in_space(point));
      } else if (is_bezier(item)) {
        for (std::size_t k = 0; k < points.size(); k += 3) boxes[t].add(in_space(points[k]));
      }
    }
  });
  for (std::size_t n : refused) {
    if (n == none) continue;
    DataError e(DataError::Problem::point_not_finite);
    e.number = n + 1;
    throw e;
  }
  BoxBuilder box;
  for (const Box& b : boxes) box.add(b);

  p.instructions.reserve(drawing.size());
  bool shapes = false;  // a conic arc's shape factor was given
  bool all_lines = true;
  // Runs of marks (or texts) of one style and shape share an invisible instruction.
  enum class Run { none, marks, texts } run = Run::none;
  Style run_style;
  MarkShape run_shape = MarkShape::square;

  auto start = [&](const Style& style, DuctArc arc, DuctMark mark, DuctPen pen) {
    DuctInstruction in;
    in.colour = std::clamp(style.pen, 1, 999999);
    in.arc = arc;
    in.mark = mark;
    in.pen = pen;
    in.dash = duct_dash(style.dash);
    p.instructions.push_back(in);
    return &p.instructions.back();
  };

  std::optional<double> extent;  // of the whole drawing, for the first rational cubic
  std::vector<Vec3> flat, controls;
  for (const auto& item : items) {
    const auto points = drawing.points(item);
    const auto w = drawing.weights(item);
    // The item's points as they are, one run of pixels.
    auto add_points = [&] { pixels.add(points.data(), points.size(), points.stride()); };
    if (item.kind != Kind::mark && item.kind != Kind::text) run = Run::none;
    switch (item.kind) {
      case Kind::polyline: {
        if (points.empty()) break;
        DuctInstruction* in = start(item.style, DuctArc::line, DuctMark::none, DuctPen::move);
        add_points();
        if (item.closed) pixels.add(points.data(), 1, points.stride());
        in->pixels = points.size() + (item.closed ? 1 : 0);
        break;
      }
      case Kind::curve: {
        if (item.degree == 3 && !is_rational(w)) {
          DuctInstruction* in = start(item.style, DuctArc::bezier, DuctMark::none, DuctPen::move);
          all_lines = false;
          add_points();
          in->pixels = points.size();
          break;
        }
        // The pixels the layout makes, from the controls.
        controls.clear();
        for (P point : points) controls.push_back(in_space(point));
        if (item.degree == 3) {
          // A rational cubic has no DUCT form: straight lines close to it.
          if (!extent) extent = extent_of(drawing);
          flat.assign(1, controls[0]);
          for (std::size_t k = 0; k + 3 < controls.size(); k += 3)
            flatten_span(3, std::span(controls).subspan(k, 4), w.subspan(k, 4), 1e-5 * *extent,
                         flat);
          DuctInstruction* in = start(item.style, DuctArc::line, DuctMark::none, DuctPen::move);
          for (Vec3 v : flat) {
            pixels.add_made(v, 0);
            box.add(v);
          }
          in->pixels = flat.size();
        } else {
          DuctInstruction* in = start(item.style, DuctArc::conic, DuctMark::none, DuctPen::move);
          all_lines = false;
          pixels.add_made(controls[0], 0);
          for (std::size_t k = 0; k + 2 < controls.size(); k += 2) {
            const double ws[3] = {w.empty() ? 1 : w[k], w.empty() ? 1 : w[k + 1],
                                  w.empty() ? 1 : w[k + 2]};
            const ConicShape cs =
                conic_shape(controls[k], controls[k + 1], controls[k + 2], ws[0], ws[1], ws[2]);
            shapes = true;
            pixels.add_made(cs.mid, cs.shape);
            pixels.add_made(controls[k + 2], 0);
            box.add_conic(controls[k], cs.mid, controls[k + 2], cs.shape);
          }
          in->pixels = controls.size();
        }
        break;
      }
      case Kind::mark: {
        if (run == Run::marks && item.style == run_style && item.shape == run_shape) {
          p.instructions.back().pixels += 1;
          p.instructions.back().mark_all = true;
        } else {
          start(item.style, DuctArc::line, duct_mark(item.shape), DuctPen::invisible)->pixels = 1;
          run = Run::marks;
          run_style = item.style;
          run_shape = item.shape;
        }
        add_points();
        break;
      }
      case Kind::text: {
        if (run == Run::texts) {
          p.instructions.back().pixels += 1;
        } else {
          start(item.style, DuctArc::line, DuctMark::none, DuctPen::invisible)->pixels = 1;
          run = Run::texts;
        }
        add_points();
        DuctText text;
        text.pixel = pixels.size();
        text.colour = std::clamp(item.style.pen, 1, 999);
        text.units = 1;
        text.angle = 0;
        text.height = 3;
        text.text = printable(drawing.text(item).substr(0, 80));
        p.texts.push_back(std::move(text));
        break;
      }
    }
  }
  // The insides of the Bézier spans, against the box of every pixel: few come near its sides.
  // Those that are not held by what is known now are looked at in order, as if every span were.
  box.settle();
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> near(parts);  // item, span
  in_parallel(parts, [&](unsigned t) {
    for (std::size_t n = cuts[t]; n < cuts[t + 1]; ++n) {
      if (!is_bezier(items[n])) continue;
      const auto points = drawing.points(items[n]);
      Vec3 span[4];
      for (std::size_t k = 0; k + 3 < points.size(); k += 3) {
        load_span<P>(points, k, span);
        if (!box.held(span)) near[t].emplace_back(n, k);
      }
    }
  });
  for (const auto& spans : near) {
    for (const auto& [n, k] : spans) {
      Vec3 span[4];
      load_span<P>(drawing.points(items[n]), k, span);
      box.add_bezier(span);
    }
  }
  if (p.instructions.empty()) {
    start(Style{}, DuctArc::line, DuctMark::none, DuctPen::invisible)->pixels = 1;
    pixels.add_made({0, 0, 0}, 0);
  }
  auto& c = p.counters;
  c[0] = 4 + (p.texts.empty() ? 0 : 2) + (shapes ? 1 : 0);
  c[1] = view.axis;
  c[2] = -1;
  c[3] = std::int64_t(p.instructions.size());
  c[4] = std::int64_t(pixels.size());
  c[5] = all_lines ? -2 : 0;
  c[6] = view.dimensions;
  c[7] = view.projected[0];
  c[8] = view.projected[1];
  c[9] = view.projected[2];
  if (!box.empty()) {
    const Box b = box.box();
    p.reals = {outwards(b.lo.x, false),
               outwards(b.hi.x, true),
               outwards(b.lo.y, false),
               outwards(b.hi.y, true),
               outwards(b.lo.z, false),
               outwards(b.hi.z, true),
               view.height};
  } else {
    p.reals = {0, 0, 0, 0, 0, 0, view.height};
  }
  return laid;
}

template Layout lay_out(const Drawing2&, const DuctHeader&, const DuctView&);
template Layout lay_out(const Drawing3&, const DuctHeader&, const DuctView&);

DuctView image_view(Projection projection) {
  DuctView view;
  view.axis = 3;
  view.dimensions = 2;
  view.projected = {static_cast<int>(projection), 0, 0};
  return view;
}

namespace {

// A drawing's picture with its pixels.
template <class P>
DuctPicture kept(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view) {
  Layout laid = lay_out(drawing, header, view);
  DuctPicture& p = laid.picture;
  const std::size_t count = laid.pixels.size();
  const bool tu = p.has_tu();
  p.xyz.reserve(3 * count);
  if (tu) p.tu.reserve(2 * count);
  laid.pixels.each(0, count, [&](const double xyz[3], double shape) {
    p.xyz.insert(p.xyz.end(), xyz, xyz + 3);
    if (tu) p.tu.insert(p.tu.end(), {shape, 0.0});
  });
  return std::move(p);
}

}  // namespace

}  // namespace duct

DuctPicture duct_picture(const Drawing3& drawing, const DuctHeader& header, const DuctView& view) {
  return duct::kept(drawing, header, view);
}

DuctPicture duct_picture(const Drawing2& drawing, const DuctHeader& header, Projection projection) {
  return duct::kept(drawing, header, duct::image_view(projection));
}

}  // namespace igds
