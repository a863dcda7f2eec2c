#include "workspace/kernels/project.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "workspace/kernels/data_error.h"

namespace igds {

namespace {

constexpr double degree = std::numbers::pi / 180;

void check_sizes(std::span<const Vec3> in, std::span<Point2> out) {
  if (out.size() != in.size()) throw std::length_error("projection: output size differs");
}

[[noreturn]] void incorrect_parameter() {
  throw DataError("INCORRECT PARAMETER");
}

Vec3 unit(Vec3 v) {
  return (1 / norm(v)) * v;
}

}  // namespace

void orthog(std::span<const Vec3> in, int plane, std::span<Point2> out) {
  check_sizes(in, out);
  // DESIM[3] numbering of the manual: 1 XY, 2 XZ, 3 YZ.
  switch (plane) {
    case 1:
      for (std::size_t k = 0; k < in.size(); ++k) out[k] = {in[k].x, in[k].y};
      return;
    case 2:
      for (std::size_t k = 0; k < in.size(); ++k) out[k] = {in[k].x, in[k].z};
      return;
    case 3:
      for (std::size_t k = 0; k < in.size(); ++k) out[k] = {in[k].y, in[k].z};
      return;
    default:
      incorrect_parameter();
  }
}

bool isom_parameters_valid(double axis, double angle_degrees) {
  return (axis == 1 || axis == 2 || axis == 3) && angle_degrees >= 0 && angle_degrees <= 90;
}

void isom(std::span<const Vec3> in, int axis, double angle_degrees, std::span<Point2> out) {
  check_sizes(in, out);
  if (!isom_parameters_valid(axis, angle_degrees)) incorrect_parameter();
  // math.md: the two kept coordinates r1, r2 in x y z order, the dropped one d drawn obliquely.
  const double c = std::cos(angle_degrees * degree), s = std::sin(angle_degrees * degree);
  for (std::size_t k = 0; k < in.size(); ++k) {
    const Vec3 p = in[k];
    double r1, r2, d;
    if (axis == 1) {
      r1 = p.y, r2 = p.z, d = p.x;
    } else if (axis == 2) {
      r1 = p.x, r2 = p.z, d = p.y;
    } else {
      r1 = p.x, r2 = p.y, d = p.z;
    }
    out[k] = {r1 + d * c, r2 + d * s};
  }
}

void conic(std::span<const Vec3> in, Vec3 view, Vec3 centre, std::span<Point2> out) {
  check_sizes(in, out);
  const Vec3 axis = centre - view;
  const double distance = norm(axis);
  if (!(distance > 0) || !std::isfinite(distance)) incorrect_parameter();
  // math.md: w towards the centre, r to the right of it, t up, z vertical on the screen.
  const Vec3 w = unit(axis);
  Vec3 side = cross(w, Vec3{0, 0, 1});
  if (norm(side) < 1e-6) side = cross(w, Vec3{0, 1, 0});
  const Vec3 r = unit(side);
  const Vec3 t = cross(r, w);
  // Refuse before writing anything: a point behind the eye has no image.
  for (const Vec3& p : in) {
    if (!(dot(p - view, w) > 0)) incorrect_parameter();
  }
  for (std::size_t k = 0; k < in.size(); ++k) {
    const Vec3 q = in[k] - view;
    const double depth = dot(q, w);
    out[k] = {distance * dot(q, r) / depth, distance * dot(q, t) / depth};
  }
}

bool asson_parameters_valid(std::array<double, 3> a) {
  for (double angle : a) {
    if (!(angle > 90 && angle < 180)) return false;
  }
  return std::abs(a[0] + a[1] + a[2] - 360) <= 1e-9;
}

void asson(std::span<const Vec3> in, std::array<double, 3> angles_degrees, std::span<Point2> out) {
  check_sizes(in, out);
  if (!asson_parameters_valid(angles_degrees)) incorrect_parameter();
  const double xy = angles_degrees[0] * degree, yz = angles_degrees[1] * degree,
               zx = angles_degrees[2] * degree;
  // math.md: foreshortenings of a true orthographic axonometric view, cyclic in x y z.
  const double kx = std::sqrt(-std::cos(yz) / (std::sin(xy) * std::sin(zx)));
  const double ky = std::sqrt(-std::cos(zx) / (std::sin(yz) * std::sin(xy)));
  const double kz = std::sqrt(-std::cos(xy) / (std::sin(zx) * std::sin(yz)));
  const double xx = -kx * std::sin(zx), xy_ = ky * std::sin(yz);
  const double yx = kx * std::cos(zx), yy = ky * std::cos(yz), yz_ = kz;
  for (std::size_t k = 0; k < in.size(); ++k) {
    const Vec3 p = in[k];
    out[k] = {xx * p.x + xy_ * p.y, yx * p.x + yy * p.y + yz_ * p.z};
  }
}

Vec3 bounding_box_centre(std::span<const Vec3> points) {
  if (points.empty()) return {};
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  // Halves first: the sum of two large coordinates could overflow.
  return {lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2, lo.z / 2 + hi.z / 2};
}

bool inside_bounding_box(std::span<const Vec3> points, Vec3 p) {
  if (points.empty()) return false;
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& q : points) {
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
  }
  return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
}

Scaling scale_into(std::span<const Point2> points, Rect target, double margin) {
  // The manual's SCALE: one factor for both axes (shapes are not distorted), image centred.
  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  for (const Point2& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
  }
  const double width = target.x1 - target.x0, height = target.y1 - target.y0;
  const double inset =
      std::clamp(std::isfinite(margin) ? margin : 0.0, 0.0, 0.45) * std::min(width, height);
  const double room_x = width - 2 * inset, room_y = height - 2 * inset;
  const double mid_x = target.x0 + width / 2, mid_y = target.y0 + height / 2;
  Scaling s;
  if (!(lo_x <= hi_x)) {
    // Nothing finite to show: the origin goes to the middle.
    s.offset_x = mid_x, s.offset_y = mid_y;
    return s;
  }
  const double span_x = hi_x - lo_x, span_y = hi_y - lo_y;
  double scale = INFINITY;
  if (span_x > 0) scale = std::min(scale, room_x / span_x);
  if (span_y > 0) scale = std::min(scale, room_y / span_y);
  if (!std::isfinite(scale)) scale = 1;  // a single point: any scale puts it in the middle
  s.scale = scale;
  s.offset_x = mid_x - scale * (lo_x / 2 + hi_x / 2);
  s.offset_y = mid_y - scale * (lo_y / 2 + hi_y / 2);
  return s;
}

}  // namespace igds
