// Small value types of the kernels: a point or vector in space, a point of an image.
#pragma once

#include <cmath>
#include <span>

#include "workspace/kernels/array.h"

namespace igds {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend bool operator==(Vec3, Vec3) = default;
};

inline double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// Overflow-safe length (hypot style).
inline double norm(Vec3 a) {
  return std::hypot(a.x, a.y, a.z);
}

struct Point2 {
  double x = 0, y = 0;
  friend bool operator==(Point2, Point2) = default;
};

static_assert(sizeof(Vec3) == 3 * sizeof(double));
static_assert(sizeof(Point2) == 2 * sizeof(double));

// Views of an array whose last axis holds x y z (or x y) as points.
inline std::span<const Vec3> as_vec3(const Array& a) {
  return {reinterpret_cast<const Vec3*>(a.data()), a.size() / 3};
}
inline std::span<Vec3> as_vec3(Array& a) {
  return {reinterpret_cast<Vec3*>(a.data()), a.size() / 3};
}
inline std::span<const Point2> as_point2(const Array& a) {
  return {reinterpret_cast<const Point2*>(a.data()), a.size() / 2};
}
inline std::span<Point2> as_point2(Array& a) {
  return {reinterpret_cast<Point2*>(a.data()), a.size() / 2};
}

}  // namespace igds
