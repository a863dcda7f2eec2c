// A drawing laid out as a DUCT picture (docs/exchange.md, "Writing"): its instructions,
// counters, limits and pixels.
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "workspace/drawing/flatten.h"
#include "workspace/drawing/project.h"
#include "workspace/exchange/duct_parts.h"
#include "workspace/kernels/data_error.h"
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
  void add(Vec3 p) { pixels_.add(p); }
  // A Bézier span, once every pixel is in: its inside is the span of the written controls,
  // worked out only when the span could reach past the box (near a flat end the written span can
  // pass its end pixel).
  void add_bezier(std::span<const Vec3> controls) {
    Vec3 most{0, 0, 0};
    for (Vec3 c : controls)
      most = {std::max(most.x, std::abs(c.x)), std::max(most.y, std::abs(c.y)),
              std::max(most.z, std::abs(c.z))};
    const Vec3 margin = 5e-7 * most;
    auto holds = [&](std::span<const Vec3> points) {
      return std::all_of(points.begin(), points.end(),
                         [&](Vec3 p) { return inside(p - margin) && inside(p + margin); });
    };
    if (holds(controls)) return;  // the span lies in its controls' hull
    Vec3 extremes[8];
    std::size_t n = span_extremes(3, controls, {}, extremes);
    extremes[n++] = controls.front();
    extremes[n++] = controls.back();
    if (holds({extremes, n})) return;
    Vec3 written[4];
    for (std::size_t k = 0; k < 4; ++k) written[k] = as_written(controls[k]);
    const std::size_t m = span_extremes(3, written, {}, extremes);
    for (std::size_t k = 0; k < m; ++k) inner_.add(extremes[k]);
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
  // The box of both: the extreme pixels as written.
  Box box() const {
    Box b = inner_;
    b.add(as_written(pixels_.lo));
    b.add(as_written(pixels_.hi));
    return b;
  }

 private:
  // Whether `p` is inside what is known of the box: the pixels' box less their rounding, and
  // the written spans' extremes.
  bool inside(Vec3 p) const {
    auto in = [](double v, double pixel_lo, double pixel_hi, double lo, double hi) {
      return v >= std::min(pixel_lo + 5e-7 * std::abs(pixel_lo), lo) &&
             v <= std::max(pixel_hi - 5e-7 * std::abs(pixel_hi), hi);
    };
    const Box& b = pixels_;
    const Box& i = inner_;
    return in(p.x, b.lo.x, b.hi.x, i.lo.x, i.hi.x) && in(p.y, b.lo.y, b.hi.y, i.lo.y, i.hi.y) &&
           in(p.z, b.lo.z, b.hi.z, i.lo.z, i.hi.z);
  }
  Box pixels_, inner_;
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

}  // namespace

template <class P>
DuctPicture lay_out(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view,
                    PixelSink* sink, bool measure) {
  using Kind = typename Drawing<P>::Kind;
  DuctPicture p;
  std::string first = printable(fmt::format("IGDS PICTURE FILE {} {}", header.name, header.date));
  p.header.push_back(first);
  if (!header.title.empty()) {
    std::string title = printable(header.title);
    if (trimmed(title) == "*") title = "(*)";
    p.header.push_back(title);
  }

  p.instructions.reserve(drawing.size());

  BoxBuilder box;
  std::size_t count = 0;  // pixels so far
  auto add_pixel = [&](Vec3 v) {
    if (sink) sink->pixel(v);
    ++count;
  };
  bool shapes = false;  // a conic arc's shape factor was given
  bool all_lines = true;
  // Runs of marks (or texts) of one style and shape share an invisible instruction.
  enum class Run { none, marks, texts } run = Run::none;
  Style run_style;
  MarkShape run_shape = MarkShape::square;

  auto bound = [&](Vec3 v) {
    if (measure) box.add(v);
  };
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
  std::vector<Vec3> flat, points;
  const auto items = drawing.items();
  for (std::size_t n = 0; n < items.size(); ++n) {
    const auto& item = items[n];
    points.clear();
    for (P point : drawing.points(item)) points.push_back(in_space(point));
    const auto w = drawing.weights(item);
    if (measure) {
      const bool bad =
          std::any_of(points.begin(), points.end(), [](Vec3 v) { return !finite(v); }) ||
          std::any_of(w.begin(), w.end(), [](double x) { return !(std::isfinite(x) && x > 0); });
      if (bad) {
        DataError e(DataError::Problem::point_not_finite);
        e.number = n + 1;
        throw e;
      }
    }
    if (item.kind != Kind::mark && item.kind != Kind::text) run = Run::none;
    switch (item.kind) {
      case Kind::polyline: {
        if (points.empty()) break;
        DuctInstruction* in = start(item.style, DuctArc::line, DuctMark::none, DuctPen::move);
        for (Vec3 v : points) {
          add_pixel(v);
          bound(v);
        }
        if (item.closed) add_pixel(points[0]);
        in->pixels = points.size() + (item.closed ? 1 : 0);
        break;
      }
      case Kind::curve: {
        const bool rational = is_rational(w);
        if (item.degree == 3 && !rational) {
          DuctInstruction* in = start(item.style, DuctArc::bezier, DuctMark::none, DuctPen::move);
          all_lines = false;
          for (Vec3 v : points) add_pixel(v);
          if (measure)
            for (std::size_t k = 0; k < points.size(); k += 3) box.add(points[k]);
          in->pixels = points.size();
        } else if (item.degree == 3) {
          // A rational cubic has no DUCT form: straight lines close to it.
          if (!extent) extent = extent_of(drawing);
          flat.assign(1, points[0]);
          for (std::size_t k = 0; k + 3 < points.size(); k += 3)
            flatten_span(3, std::span(points).subspan(k, 4), w.subspan(k, 4), 1e-5 * *extent, flat);
          DuctInstruction* in = start(item.style, DuctArc::line, DuctMark::none, DuctPen::move);
          for (Vec3 v : flat) {
            add_pixel(v);
            bound(v);
          }
          in->pixels = flat.size();
        } else {
          DuctInstruction* in = start(item.style, DuctArc::conic, DuctMark::none, DuctPen::move);
          all_lines = false;
          add_pixel(points[0]);
          for (std::size_t k = 0; k + 2 < points.size(); k += 2) {
            const double ws[3] = {w.empty() ? 1 : w[k], w.empty() ? 1 : w[k + 1],
                                  w.empty() ? 1 : w[k + 2]};
            const ConicShape cs =
                conic_shape(points[k], points[k + 1], points[k + 2], ws[0], ws[1], ws[2]);
            if (sink) sink->shape(cs.shape);
            shapes = true;
            add_pixel(cs.mid);
            add_pixel(points[k + 2]);
            if (measure) box.add_conic(points[k], cs.mid, points[k + 2], cs.shape);
          }
          in->pixels = points.size();
        }
        break;
      }
      case Kind::mark: {
        const Vec3 v = points[0];
        bound(v);
        if (run == Run::marks && item.style == run_style && item.shape == run_shape) {
          p.instructions.back().pixels += 1;
          p.instructions.back().mark_all = true;
        } else {
          start(item.style, DuctArc::line, duct_mark(item.shape), DuctPen::invisible)->pixels = 1;
          run = Run::marks;
          run_style = item.style;
          run_shape = item.shape;
        }
        add_pixel(v);
        break;
      }
      case Kind::text: {
        const Vec3 v = points[0];
        bound(v);
        if (run == Run::texts) {
          p.instructions.back().pixels += 1;
        } else {
          start(item.style, DuctArc::line, DuctMark::none, DuctPen::invisible)->pixels = 1;
          run = Run::texts;
        }
        add_pixel(v);
        DuctText text;
        text.pixel = count;
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
  if (measure) {
    for (const auto& item : items) {
      if (item.kind != Kind::curve || item.degree != 3 || is_rational(drawing.weights(item)))
        continue;
      points.clear();
      for (P point : drawing.points(item)) points.push_back(in_space(point));
      for (std::size_t k = 0; k + 3 < points.size(); k += 3)
        box.add_bezier(std::span(points).subspan(k, 4));
    }
  }
  if (p.instructions.empty()) {
    start(Style{}, DuctArc::line, DuctMark::none, DuctPen::invisible)->pixels = 1;
    add_pixel({0, 0, 0});
  }
  auto& c = p.counters;
  c[0] = 4 + (p.texts.empty() ? 0 : 2) + (shapes ? 1 : 0);
  c[1] = view.axis;
  c[2] = -1;
  c[3] = std::int64_t(p.instructions.size());
  c[4] = std::int64_t(count);
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
  return p;
}

template DuctPicture lay_out(const Drawing2&, const DuctHeader&, const DuctView&, PixelSink*, bool);
template DuctPicture lay_out(const Drawing3&, const DuctHeader&, const DuctView&, PixelSink*, bool);

DuctView image_view(Projection projection) {
  DuctView view;
  view.axis = 3;
  view.dimensions = 2;
  view.projected = {static_cast<int>(projection), 0, 0};
  return view;
}

namespace {

// The pixels of a picture kept in it.
class KeptPixels final : public PixelSink {
 public:
  explicit KeptPixels(DuctPicture& p) : p_(p) {}
  void shape(double s) override { shapes_.emplace_back(p_.pixel_count(), s); }
  void pixel(Vec3 v) override { p_.xyz.insert(p_.xyz.end(), {v.x, v.y, v.z}); }
  // T U of `count` pixels, T the shape factors given.
  void put_shapes(std::vector<double>& tu, std::size_t count) const {
    tu.assign(2 * count, 0.0);
    for (const auto& [pixel, s] : shapes_) tu[2 * pixel] = s;
  }

 private:
  DuctPicture& p_;
  std::vector<std::pair<std::size_t, double>> shapes_;  // pixel, shape factor
};

template <class P>
DuctPicture kept(const Drawing<P>& drawing, const DuctHeader& header, const DuctView& view) {
  DuctPicture pixels;
  // Room for every pixel at once: a picture of millions of them is not copied as it grows.
  std::size_t count = 0;
  for (const auto& item : drawing.items()) count += item.count + (item.closed ? 1 : 0);
  pixels.xyz.reserve(3 * count);
  KeptPixels out(pixels);
  DuctPicture laid = lay_out(drawing, header, view, &out, true);
  laid.xyz = std::move(pixels.xyz);
  if (laid.has_tu()) out.put_shapes(laid.tu, laid.pixel_count());
  return laid;
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
