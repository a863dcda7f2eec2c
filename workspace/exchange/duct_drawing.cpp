// A DUCT picture as a drawing in space (docs/exchange.md, "Drawing a picture"): its conic arcs,
// Bézier spans and lines, marks, dashes and texts.
#include <cmath>
#include <stdexcept>

#include "workspace/exchange/duct.h"

namespace igds {

// ---------------------------------------------------------------------------------------------
// Conic arcs (docs/exchange.md, "Conic arcs": the weights derived and checked).

ConicSpans conic_spans(Vec3 p0, Vec3 m, Vec3 p1, double shape) {
  ConicSpans out;
  const Vec3 chord = p1 - p0;
  const double c2 = dot(chord, chord);
  const double b = 2 * norm(cross(m - p0, chord)) / c2;
  const double f = 1 + shape * b * b;
  auto finite = [](Vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  if (c2 > 0 && std::isfinite(c2) && std::isfinite(f) && f > 0) {
    if (f < 2) {
      // One span: the rational quadratic of docs/exchange.md ("Conic arcs") in Bernstein form.
      const double w = (2 - f) / f;
      const Vec3 q = 0.5 * (p0 + p1);
      const Vec3 control = (1 / (2 - f)) * (2 * m - f * q);
      if (finite(control) && std::isfinite(w) && w > 0) {
        out.spans = 1;
        out.controls = {p0, control, p1, {}, {}};
        out.weights = {1, w, 1, 0, 0};
        return out;
      }
    }
    // Two spans split at M (de Casteljau at t = 1/2 in homogeneous coordinates): controls
    // M -/+ f(P1 - P0)/4, weights 1/f at the three inner controls.
    const Vec3 half = (f / 4) * chord;
    const double w = 1 / f;
    if (finite(half) && w > 0) {
      out.spans = 2;
      out.controls = {p0, m - half, m, m + half, p1};
      out.weights = {1, w, w, w, 1};
      return out;
    }
  }
  out.spans = 2;
  out.lines = true;
  out.controls = {p0, 0.5 * (p0 + m), m, 0.5 * (m + p1), p1};
  out.weights = {1, 1, 1, 1, 1};
  return out;
}

ConicShape conic_shape(Vec3 p0, Vec3 c, Vec3 p1, double w0, double w1, double w2) {
  // In standard form (end weights 1) the middle weight is w1/sqrt(w0 w2); M is the point at
  // t = 1/2 and f = 2/(1 + w) (the inverse of conic_spans).
  const double w = w1 / std::sqrt(w0 * w2);
  ConicShape out;
  // M = (Q + wC)/(1 + w) with Q the chord's middle, in a form that cannot overflow.
  out.mid = (1 / (1 + w)) * (0.5 * p0 + 0.5 * p1) + (w / (1 + w)) * c;
  const Vec3 chord = p1 - p0;
  const double c2 = dot(chord, chord);
  const double b = c2 > 0 ? 2 * norm(cross(out.mid - p0, chord)) / c2 : 0;
  const double f = 2 / (1 + w);
  out.shape = b > 0 && std::isfinite(b) ? (f - 1) / (b * b) : 0;
  if (!std::isfinite(out.shape)) out.shape = 0;
  return out;
}

// ---------------------------------------------------------------------------------------------
// Picture to drawing.

namespace {

MarkShape mark_shape(DuctMark m) {
  switch (m) {
    case DuctMark::cross:
      return MarkShape::cross;
    case DuctMark::plus:
      return MarkShape::plus;
    case DuctMark::diamond:
      return MarkShape::diamond;
    case DuctMark::square:
    case DuctMark::none:
      break;
  }
  return MarkShape::square;
}

Dash dash_of(DuctDash d) {
  switch (d) {
    case DuctDash::dashed:
      return Dash::dashed;
    case DuctDash::chain:
      return Dash::chain;
    case DuctDash::solid:
      break;
  }
  return Dash::solid;
}

}  // namespace

Drawing3 duct_drawing(const DuctPicture& picture) {
  std::size_t total = 0;
  for (const auto& in : picture.instructions) total += in.pixels;
  if (total * 3 != picture.xyz.size() || (!picture.tu.empty() && picture.tu.size() != 2 * total))
    throw std::invalid_argument("DUCT picture: the pixels do not add up");
  for (const auto& t : picture.texts)
    if (t.pixel < 1 || t.pixel > total)
      throw std::invalid_argument("DUCT picture: a text at no pixel");

  Drawing3 d;
  auto pixel = [&](std::size_t k) { return Vec3::load(&picture.xyz[3 * k]); };
  std::vector<double> curve, chain, weights;
  std::size_t next = 0;  // the first pixel of the instruction
  bool have_last = false;
  Vec3 last;
  for (std::size_t n = 0; n < picture.instructions.size(); ++n) {
    const DuctInstruction& in = picture.instructions[n];
    const Style style{.pen = in.colour < 1 ? 1 : in.colour, .dash = dash_of(in.dash)};
    const Identity id{Role::line, int(n + 1)};
    const bool continued = in.pen == DuctPen::continued && have_last;
    if (in.pen == DuctPen::continued && !have_last)
      throw std::invalid_argument("DUCT picture: IUPDN 24 with no previous pixel");
    // The instruction's curve: its pixels, after the previous last pixel for IUPDN 24.
    curve.clear();
    if (continued) curve.insert(curve.end(), {last.x, last.y, last.z});
    curve.insert(curve.end(), picture.xyz.begin() + std::ptrdiff_t(3 * next),
                 picture.xyz.begin() + std::ptrdiff_t(3 * (next + in.pixels)));
    const std::size_t count = curve.size() / 3;
    const Vec3View points(curve.data(), count);
    const bool join = in.pen == DuctPen::visible && have_last;
    const bool drawn = in.pen != DuctPen::invisible;

    switch (in.arc) {
      case DuctArc::line:
        if (drawn) {
          if (join) {
            std::vector<double> joined = {last.x, last.y, last.z};
            joined.insert(joined.end(), curve.begin(), curve.end());
            d.add_polyline(Vec3View(joined.data(), count + 1), style, id);
          } else if (count >= 2) {
            d.add_polyline(points, style, id);
          }
        }
        break;
      case DuctArc::bezier:
        if (drawn) {
          if (join) {
            const double line[6] = {last.x, last.y, last.z, curve[0], curve[1], curve[2]};
            d.add_polyline(Vec3View(line, 2), style, id);
          }
          if (count >= 4) d.add_curve(3, points, {}, style, id);
        }
        break;
      case DuctArc::conic:
        if (drawn) {
          if (join) {
            const double line[6] = {last.x, last.y, last.z, curve[0], curve[1], curve[2]};
            d.add_polyline(Vec3View(line, 2), style, id);
          }
          if (count >= 3) {
            chain.clear();
            weights.clear();
            chain.insert(chain.end(), curve.begin(), curve.begin() + 3);
            weights.push_back(1);
            for (std::size_t k = 1; k + 1 < count; k += 2) {
              // The mid point's T is its shape factor; without TU parameters, 1.
              const std::size_t file_pixel = next + k - (continued ? 1 : 0);
              const double s = picture.tu.empty() ? 1.0 : picture.tu[2 * file_pixel];
              const ConicSpans spans = conic_spans(points[k - 1], points[k], points[k + 1], s);
              for (int c = 1; c <= 2 * spans.spans; ++c) {
                const Vec3 v = spans.controls[std::size_t(c)];
                chain.insert(chain.end(), {v.x, v.y, v.z});
                weights.push_back(spans.weights[std::size_t(c)]);
              }
            }
            d.add_curve(2, Vec3View(chain.data(), chain.size() / 3), weights, style, id);
          }
        }
        break;
    }

    if (in.mark != DuctMark::none) {
      const std::size_t step = in.arc == DuctArc::conic ? 2 : in.arc == DuctArc::bezier ? 3 : 1;
      for (std::size_t k = 0; k < count; k += step) {
        d.add_mark(points[k], mark_shape(in.mark), duct_mark_size, style, id);
        if (!in.mark_all) break;
      }
    }
    last = points[count - 1];
    have_last = true;
    next += in.pixels;
  }

  for (std::size_t t = 0; t < picture.texts.size(); ++t) {
    const DuctText& text = picture.texts[t];
    d.add_text(pixel(text.pixel - 1), text.text, 1, Style{.pen = text.colour < 1 ? 1 : text.colour},
               Identity{Role::label, int(t + 1), int(text.pixel)});
  }
  return d;
}

}  // namespace igds
