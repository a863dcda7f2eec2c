// Test helpers of the kernels: reproducible grids, an independent evaluation of a patch matrix.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "workspace/kernels/array.h"
#include "workspace/kernels/vec3.h"

namespace igds::test {

// The box of the `n` points x y at `xy` (2n numbers), x0 y0 x1 y1, found one point at a time: what
// the kernels' one-pass boxes are checked against.
inline std::array<double, 4> box_of_points(const double* xy, std::size_t n) {
  std::array<double, 4> box{xy[0], xy[1], xy[0], xy[1]};
  for (std::size_t k = 0; k < n; ++k) {
    const double x = xy[2 * k], y = xy[2 * k + 1];
    box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
  }
  return box;
}

// A small deterministic generator (SplitMix64) so that every run sees the same data.
struct Random {
  std::uint64_t state;
  explicit Random(std::uint64_t seed) : state(seed) {}
  double uniform(double lo, double hi) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return lo + (hi - lo) * double(z >> 11) * 0x1.0p-53;
  }
  Vec3 vec(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
};

// Points kept as doubles, as the kernels' views want them, made from a list of points.
template <class P>
struct Flat {
  std::vector<double> d;
  Flat() = default;
  Flat(std::initializer_list<P> points) { assign(std::vector<P>(points)); }
  explicit Flat(const std::vector<P>& points) { assign(points); }
  explicit Flat(std::size_t n, P fill = {}) { assign(std::vector<P>(n, fill)); }
  void assign(const std::vector<P>& points) {
    d.assign(P::dimension * points.size(), 0.0);
    for (std::size_t i = 0; i < points.size(); ++i) points[i].store(&d[P::dimension * i]);
  }
  Flat& operator=(std::initializer_list<P> points) {
    assign(std::vector<P>(points));
    return *this;
  }
  std::size_t size() const { return d.size() / P::dimension; }
  void resize(std::size_t n) { d.resize(P::dimension * n); }
  P operator[](std::size_t i) const { return P::load(&d[P::dimension * i]); }
  void set(std::size_t i, P p) { p.store(&d[P::dimension * i]); }
  P back() const { return (*this)[size() - 1]; }
  operator PointsView<P, const double>() const { return {d.data(), size()}; }
  operator PointsView<P, double>() { return {d.data(), size()}; }
  std::vector<P> points() const {
    std::vector<P> out(size());
    for (std::size_t i = 0; i < size(); ++i) out[i] = (*this)[i];
    return out;
  }
};

inline double distance(Vec3 a, Vec3 b) {
  return norm(a - b);
}

// A wavy NOCUR x NOSTR grid with uneven spacing (INPPN) and random border tangents (INPTG, with
// the point numbers in column 4 as workspace/state.h describes).
struct Grid {
  int nocur, nostr;
  Array inppn, inptg;
};

inline Grid wavy_grid(int nocur, int nostr, std::uint64_t seed) {
  Random rnd(seed);
  Grid g{nocur, nostr, Array({std::size_t(nocur * nostr), 3}),
         Array({std::size_t(2 * (nocur + nostr)), 4})};
  std::vector<double> xs(nostr), ys(nocur);
  double x = 0, y = 0;
  for (auto& v : xs) v = (x += rnd.uniform(0.5, 2.0));
  for (auto& v : ys) v = (y += rnd.uniform(0.5, 2.0));
  auto pts = as_vec3(g.inppn);
  for (int i = 0; i < nocur; ++i) {
    for (int j = 0; j < nostr; ++j) {
      pts[i * nostr + j] = {xs[j] + rnd.uniform(-0.1, 0.1), ys[i] + rnd.uniform(-0.1, 0.1),
                            std::sin(xs[j]) * std::cos(0.7 * ys[i]) + rnd.uniform(-0.2, 0.2)};
    }
  }
  double* t = g.inptg.data();
  auto row = [&](int r, Vec3 v, int point) {
    t[4 * r] = v.x, t[4 * r + 1] = v.y, t[4 * r + 2] = v.z, t[4 * r + 3] = point;
  };
  for (int i = 0; i < nocur; ++i) {
    row(2 * i, Vec3{1, 0, 0} + rnd.vec(-0.3, 0.3), i * nostr + 1);
    row(2 * i + 1, Vec3{1, 0, 0} + rnd.vec(-0.3, 0.3), i * nostr + nostr);
  }
  for (int j = 0; j < nostr; ++j) {
    row(2 * nocur + 2 * j, Vec3{0, 1, 0} + rnd.vec(-0.3, 0.3), j + 1);
    row(2 * nocur + 2 * j + 1, Vec3{0, 1, 0} + rnd.vec(-0.3, 0.3), (nocur - 1) * nostr + j + 1);
  }
  return g;
}

// P(u,v) = [F0(u) F1(u) G0(u) G1(u)] M [F0(v) F1(v) G0(v) G1(v)]^T of one patch (docs/kernels.md),
// written out here independently of the kernels.
inline Vec3 eval_patch(const double* m, double u, double v) {
  auto basis = [](double s, double b[4]) {
    b[0] = 2 * s * s * s - 3 * s * s + 1;
    b[1] = -2 * s * s * s + 3 * s * s;
    b[2] = s * s * s - 2 * s * s + s;
    b[3] = s * s * s - s * s;
  };
  double bu[4], bv[4], out[3] = {0, 0, 0};
  basis(u, bu);
  basis(v, bv);
  for (int k = 0; k < 3; ++k)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out[k] += bu[r] * m[16 * k + 4 * r + c] * bv[c];
  return {out[0], out[1], out[2]};
}

// Largest distance between corresponding points of two arrays of points.
inline double max_distance(const Array& a, const Array& b) {
  auto pa = as_vec3(a), pb = as_vec3(b);
  double worst = 0;
  for (std::size_t k = 0; k < std::min(pa.size(), pb.size()); ++k)
    worst = std::max(worst, distance(pa[k], pb[k]));
  return worst;
}

}  // namespace igds::test
