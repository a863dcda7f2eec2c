#include "workspace/drawing/flatten.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace igds {

namespace {

// A control point in homogeneous coordinates: (x w, y w, w) in the plane, (x w, y w, z w, w) in
// space.
struct H2 {
  double x, y, w;
};
struct H3 {
  double x, y, z, w;
};
H2 mid(H2 a, H2 b) {
  return {(a.x + b.x) / 2, (a.y + b.y) / 2, (a.w + b.w) / 2};
}
H3 mid(H3 a, H3 b) {
  return {(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2, (a.w + b.w) / 2};
}
Point2 point(H2 h) {
  return {h.x / h.w, h.y / h.w};
}
Vec3 point(H3 h) {
  return {h.x / h.w, h.y / h.w, h.z / h.w};
}
H2 lifted(Point2 p, double w) {
  return {p.x * w, p.y * w, w};
}
H3 lifted(Vec3 p, double w) {
  return {p.x * w, p.y * w, p.z * w, w};
}
bool finite(Point2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}
bool finite(Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// A chord from a to b, and how far a point lies from its line (from a, when it has no length).
struct Chord2 {
  Point2 a;
  double dx, dy, len;
  Chord2(Point2 from, Point2 to)
      : a(from), dx(to.x - from.x), dy(to.y - from.y), len(std::hypot(dx, dy)) {}
  double distance(Point2 p) const {
    if (len == 0) return std::hypot(p.x - a.x, p.y - a.y);
    return std::abs((p.x - a.x) * dy - (p.y - a.y) * dx) / len;
  }
};
struct Chord3 {
  Vec3 a, chord;
  double length;
  Chord3(Vec3 from, Vec3 to) : a(from), chord(to - from), length(norm(chord)) {}
  double distance(Vec3 p) const {
    const Vec3 v = p - a;
    return length > 0 ? norm(cross(v, chord)) / length : norm(v);
  }
};
Chord2 chord_of(Point2 a, Point2 b) {
  return {a, b};
}
Chord3 chord_of(Vec3 a, Vec3 b) {
  return {a, b};
}

// Flat when every control point lies within the tolerance of the chord: then the curve, inside
// the hull of its controls (the weights being positive), does too.
template <class H>
bool flat(const std::array<H, 4>& c, int degree, double tolerance) {
  const auto chord = chord_of(point(c[0]), point(c[static_cast<std::size_t>(degree)]));
  for (int k = 1; k < degree; ++k)
    if (chord.distance(point(c[static_cast<std::size_t>(k)])) > tolerance) return false;
  return true;
}

template <class H, class P>
void subdivide(const std::array<H, 4>& c, int degree, double tolerance, int depth,
               std::vector<P>& out) {
  // The depth bound only stops a curve of non-finite or absurd coordinates from recursing on.
  if (depth >= 40 || flat(c, degree, tolerance)) {
    out.push_back(point(c[static_cast<std::size_t>(degree)]));
    return;
  }
  std::array<H, 4> left, right;  // the first degree + 1 of each are set
  if (degree == 2) {
    const H p01 = mid(c[0], c[1]), p12 = mid(c[1], c[2]), p = mid(p01, p12);
    left = {c[0], p01, p};
    right = {p, p12, c[2]};
  } else {
    const H p01 = mid(c[0], c[1]), p12 = mid(c[1], c[2]), p23 = mid(c[2], c[3]);
    const H p012 = mid(p01, p12), p123 = mid(p12, p23), p = mid(p012, p123);
    left = {c[0], p01, p012, p};
    right = {p, p123, p23, c[3]};
  }
  subdivide(left, degree, tolerance, depth + 1, out);
  subdivide(right, degree, tolerance, depth + 1, out);
}

template <class H, class P>
void flatten(int degree, std::span<const P> controls, std::span<const double> weights,
             double tolerance, std::vector<P>& out) {
  std::array<H, 4> c{};
  for (int k = 0; k <= degree; ++k) {
    const double w = weights.empty() ? 1.0 : weights[static_cast<std::size_t>(k)];
    c[static_cast<std::size_t>(k)] = lifted(controls[static_cast<std::size_t>(k)], w);
  }
  if (out.empty()) out.push_back(controls[0]);
  const bool all_finite =
      std::all_of(controls.begin(), controls.begin() + degree + 1, [](P p) { return finite(p); });
  if (!all_finite || !(tolerance > 0)) {
    out.push_back(controls[static_cast<std::size_t>(degree)]);
    return;
  }
  subdivide(c, degree, tolerance, 0, out);
}

// The roots in (0, 1) of a t^2 + b t + c at `roots`; returns how many.
int unit_roots(double a, double b, double c, double roots[2]) {
  int n = 0;
  auto keep = [&](double t) {
    if (t > 0 && t < 1) roots[n++] = t;
  };
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
  if (scale == 0) return 0;
  if (std::abs(a) <= 1e-12 * scale) {
    if (b != 0) keep(-c / b);
    return n;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  keep(q / a);
  if (q != 0) keep(c / q);
  return n;
}

double coordinate(Vec3 v, int k) {
  return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

Vec3 cubic_point(std::span<const Vec3> c, double t) {
  const double s = 1 - t;
  return (s * s * s) * c[0] + (3 * s * s * t) * c[1] + (3 * s * t * t) * c[2] + (t * t * t) * c[3];
}

Vec3 quadratic_point(std::span<const Vec3> c, const double w[3], double t) {
  const double s = 1 - t;
  const double b0 = s * s * w[0], b1 = 2 * s * t * w[1], b2 = t * t * w[2];
  return (1 / (b0 + b1 + b2)) * (b0 * c[0] + b1 * c[1] + b2 * c[2]);
}

}  // namespace

void flatten_span(int degree, std::span<const Point2> controls, std::span<const double> weights,
                  double tolerance, std::vector<Point2>& out) {
  flatten<H2>(degree, controls, weights, tolerance, out);
}

void flatten_span(int degree, std::span<const Vec3> controls, std::span<const double> weights,
                  double tolerance, std::vector<Vec3>& out) {
  flatten<H3>(degree, controls, weights, tolerance, out);
}

std::size_t span_extremes(int degree, std::span<const Vec3> c, std::span<const double> weights,
                          Vec3 out[6]) {
  std::size_t n = 0;
  double roots[2];
  if (degree == 3) {
    for (int k = 0; k < 3; ++k) {
      const double x0 = coordinate(c[0], k), x1 = coordinate(c[1], k), x2 = coordinate(c[2], k),
                   x3 = coordinate(c[3], k);
      // The derivative's Bernstein coefficients 3(x1-x0), 3(x2-x1), 3(x3-x2) in the power basis.
      const double a = -x0 + 3 * x1 - 3 * x2 + x3, b = 2 * (x0 - 2 * x1 + x2), cc = x1 - x0;
      const int m = unit_roots(a, b, cc, roots);
      for (int r = 0; r < m; ++r) out[n++] = cubic_point(c, roots[r]);
    }
    return n;
  }
  const double w[3] = {weights.empty() ? 1 : weights[0], weights.empty() ? 1 : weights[1],
                       weights.empty() ? 1 : weights[2]};
  // x = N/D with N and D quadratics; N'D - ND' is a quadratic (its cubic terms cancel).
  const double d0 = w[0], d1 = 2 * (w[1] - w[0]), d2 = w[0] - 2 * w[1] + w[2];
  for (int k = 0; k < 3; ++k) {
    const double y0 = w[0] * coordinate(c[0], k), y1 = w[1] * coordinate(c[1], k),
                 y2 = w[2] * coordinate(c[2], k);
    const double n0 = y0, n1 = 2 * (y1 - y0), n2 = y0 - 2 * y1 + y2;
    const int m = unit_roots(n2 * d1 - n1 * d2, 2 * (n2 * d0 - n0 * d2), n1 * d0 - n0 * d1, roots);
    for (int r = 0; r < m; ++r) out[n++] = quadratic_point(c, w, roots[r]);
  }
  return n;
}

}  // namespace igds
