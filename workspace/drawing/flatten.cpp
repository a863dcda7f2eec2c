#include "workspace/drawing/flatten.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace igds {

namespace {

// A control point in homogeneous coordinates: (x w, y w, w).
struct H {
  double x, y, w;
};
H mid(H a, H b) {
  return {(a.x + b.x) / 2, (a.y + b.y) / 2, (a.w + b.w) / 2};
}
Point2 point(H h) {
  return {h.x / h.w, h.y / h.w};
}

double distance_to_chord(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  if (len == 0) return std::hypot(p.x - a.x, p.y - a.y);
  return std::abs((p.x - a.x) * dy - (p.y - a.y) * dx) / len;
}

// Flat when every control point lies within the tolerance of the chord and the weights do not
// vary much: then the curve, inside the hull of its controls, does too.
bool flat(const std::array<H, 4>& c, int degree, double tolerance) {
  const Point2 a = point(c[0]), b = point(c[static_cast<std::size_t>(degree)]);
  for (int k = 1; k < degree; ++k)
    if (distance_to_chord(point(c[static_cast<std::size_t>(k)]), a, b) > tolerance) return false;
  return true;
}

void subdivide(std::array<H, 4> c, int degree, double tolerance, int depth,
               std::vector<Point2>& out) {
  // The depth bound only stops a curve of non-finite or absurd coordinates from recursing on.
  if (depth >= 40 || flat(c, degree, tolerance)) {
    out.push_back(point(c[static_cast<std::size_t>(degree)]));
    return;
  }
  std::array<H, 4> left{}, right{};
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

}  // namespace

void flatten_span(int degree, std::span<const Point2> controls, std::span<const double> weights,
                  double tolerance, std::vector<Point2>& out) {
  std::array<H, 4> c{};
  for (int k = 0; k <= degree; ++k) {
    const double w = weights.empty() ? 1.0 : weights[static_cast<std::size_t>(k)];
    const Point2 p = controls[static_cast<std::size_t>(k)];
    c[static_cast<std::size_t>(k)] = {p.x * w, p.y * w, w};
  }
  if (out.empty()) out.push_back(controls[0]);
  const bool finite = std::all_of(controls.begin(), controls.begin() + degree + 1, [](Point2 p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
  });
  if (!finite || !(tolerance > 0)) {
    out.push_back(controls[static_cast<std::size_t>(degree)]);
    return;
  }
  subdivide(c, degree, tolerance, 0, out);
}

}  // namespace igds
