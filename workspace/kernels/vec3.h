// Small value types of the kernels: a point or vector in space, a point of an image, and views
// of the arrays of doubles that hold them (x y z, x y z, ...).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <span>
#include <type_traits>

#include "workspace/kernels/array.h"

namespace igds {

struct Vec3 {
  static constexpr std::size_t dimension = 3;
  double x = 0, y = 0, z = 0;
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend bool operator==(Vec3, Vec3) = default;
  static Vec3 load(const double* d) { return {d[0], d[1], d[2]}; }
  void store(double* d) const { d[0] = x, d[1] = y, d[2] = z; }
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

// A box in space, its sides parallel to the axes: empty (lo above hi) until a point is added.
struct Box3 {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  bool empty() const { return !(lo.x <= hi.x); }
  void add(Vec3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  // Each coordinate on its own: a box empty on one axis (its points' coordinates there all NaN)
  // adds nothing on that axis.
  void add(const Box3& b) {
    lo = {std::min(lo.x, b.lo.x), std::min(lo.y, b.lo.y), std::min(lo.z, b.lo.z)};
    hi = {std::max(hi.x, b.hi.x), std::max(hi.y, b.hi.y), std::max(hi.z, b.hi.z)};
  }
  // Halves first: the sum of two large coordinates could overflow.
  Vec3 centre() const { return {lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2, lo.z / 2 + hi.z / 2}; }
  bool contains(Vec3 p) const {
    return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
  }
};

struct Point2 {
  static constexpr std::size_t dimension = 2;
  double x = 0, y = 0;
  friend bool operator==(Point2, Point2) = default;
  static Point2 load(const double* d) { return {d[0], d[1]}; }
  void store(double* d) const { d[0] = x, d[1] = y; }
};

// A view of `size()` points kept as consecutive doubles (the last axis of an APL array). Points
// are read and written by value through the doubles, never as Vec3 or Point2 objects laid over
// them: the language allows only that (strict aliasing).
template <class P, class Double>
class PointsView {
 public:
  static constexpr std::size_t n = P::dimension;

  // Reading yields a P; writing through a non-const view stores one.
  class Ref {
   public:
    explicit Ref(Double* d) : d_(d) {}
    operator P() const { return P::load(d_); }
    Ref& operator=(P v) {
      v.store(d_);
      return *this;
    }
    Ref& operator=(const Ref& other) { return *this = P(other); }
    Ref(const Ref&) = default;

   private:
    Double* d_;
  };

  // Walks by index, so that no pointer ever goes past the end of the array (a column's end
  // would).
  class iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = P;
    using difference_type = std::ptrdiff_t;
    iterator() = default;
    iterator(Double* d, std::size_t i, std::size_t stride) : d_(d), i_(i), stride_(stride) {}
    auto operator*() const {
      if constexpr (std::is_const_v<Double>)
        return P::load(d_ + stride_ * i_);
      else
        return Ref(d_ + stride_ * i_);
    }
    iterator& operator++() {
      ++i_;
      return *this;
    }
    iterator operator++(int) {
      iterator old = *this;
      ++i_;
      return old;
    }
    friend bool operator==(iterator a, iterator b) { return a.i_ == b.i_; }

   private:
    Double* d_ = nullptr;
    std::size_t i_ = 0, stride_ = n;
  };

  PointsView() = default;
  // `count` points from `data`, `stride` doubles apart (n when they follow each other; a column
  // of a grid has the row's length times n).
  PointsView(Double* data, std::size_t count, std::size_t stride = n)
      : data_(data), count_(count), stride_(stride) {}
  // A const view of a mutable one.
  template <class Other>
  requires(std::is_const_v<Double> && !std::is_const_v<Other>)
      PointsView(PointsView<P, Other> other)
      : data_(other.data()), count_(other.size()), stride_(other.stride()) {}

  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  Double* data() const { return data_; }
  std::size_t stride() const { return stride_; }
  auto operator[](std::size_t i) const { return *iterator(data_, i, stride_); }
  P front() const { return P::load(data_); }
  P back() const { return P::load(data_ + stride_ * (count_ - 1)); }
  PointsView subspan(std::size_t first, std::size_t count) const {
    return {data_ + stride_ * first, count, stride_};
  }
  iterator begin() const { return iterator(data_, 0, stride_); }
  iterator end() const { return iterator(data_, count_, stride_); }

 private:
  Double* data_ = nullptr;
  std::size_t count_ = 0;
  std::size_t stride_ = n;
};

using Vec3View = PointsView<Vec3, const double>;
using MutableVec3View = PointsView<Vec3, double>;
using Point2View = PointsView<Point2, const double>;
using MutablePoint2View = PointsView<Point2, double>;

// Views of an array whose last axis holds x y z (or x y) as points.
inline Vec3View as_vec3(const Array& a) {
  return {a.data(), a.size() / 3};
}
inline MutableVec3View as_vec3(Array& a) {
  return {a.data(), a.size() / 3};
}
inline Point2View as_point2(const Array& a) {
  return {a.data(), a.size() / 2};
}
inline MutablePoint2View as_point2(Array& a) {
  return {a.data(), a.size() / 2};
}

}  // namespace igds
