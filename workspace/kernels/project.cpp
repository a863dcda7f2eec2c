#include "workspace/kernels/project.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "workspace/kernels/conic_lanes.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/parallel.h"
#include "workspace/kernels/processor.h"

namespace igds {

namespace {

constexpr double degree = std::numbers::pi / 180;

void check_sizes(Vec3View in, MutablePoint2View out) {
  if (out.size() != in.size()) throw std::length_error("projection: output size differs");
}

[[noreturn]] void refuse(DataError::Problem problem) {
  throw DataError(problem);
}

Vec3 unit(Vec3 v) {
  return (1 / norm(v)) * v;
}

// A parallel projection's 2 x 3 matrix: X = xx x + xy y, Y = yx x + yy y + yz z.
struct AssonMatrix {
  double xx, xy, yx, yy, yz;
};

// PROSPAR's matrix: the x axis drawn at angle px and the y axis at angle py (radians, from the
// screen's x axis), z upright, each unit long.
AssonMatrix prospar_matrix(double px, double py) {
  return {-std::sin(px), std::sin(py), std::cos(px), std::cos(py), 1};
}

// ASSON's matrix (docs/kernels.md): PROSPAR's with the axes at the angles z-x and y-z, each axis
// foreshortened as a true orthographic axonometric view makes it (the manual's ASSON: the
// points scaled, then PROSPAR).
AssonMatrix asson_matrix(std::array<double, 3> angles_degrees) {
  const double xy = angles_degrees[0] * degree, yz = angles_degrees[1] * degree,
               zx = angles_degrees[2] * degree;
  const double kx = std::sqrt(-std::cos(yz) / (std::sin(xy) * std::sin(zx)));
  const double ky = std::sqrt(-std::cos(zx) / (std::sin(yz) * std::sin(xy)));
  const double kz = std::sqrt(-std::cos(xy) / (std::sin(zx) * std::sin(yz)));
  const AssonMatrix p = prospar_matrix(zx, yz);
  return {p.xx * kx, p.xy * ky, p.yx * kx, p.yy * ky, p.yz * kz};
}

bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// What one pass of a projection over its points found: the first point whose image is not finite
// (the count of points: none) and the box of the images; CONIC's too, whether a point is not in
// front of the eye and the box of the points about the eye (p - eye).
struct Pass {
  std::size_t not_finite;
  bool behind = false;
  Box3 about_eye;
  bool box = false;  // asked for the box of the points: `points`
  Box3 points;
  static constexpr double inf = std::numeric_limits<double>::infinity();
  Point2 low{inf, inf}, high{-inf, -inf};
};

// out[k] = image(in[k]) for every point, on the machine's cores for a large image, each image
// checked as it is made: x * 0 is 0 for a finite x and NaN for the rest (docs/kernels.md, "Data
// checks"), summed a block at a time. `block(from, to, pass)` makes the images of [from, to) and
// returns that sum, and keeps in `pass` the box of the images (CONIC also whether a point is not in
// front of the eye and the box of the points about it).
template <class Block>
Pass each_block(Vec3View in, MutablePoint2View out, const Block& block, bool box) {
  const std::size_t n = in.size();
  // Counted in points: a point's image costs about what a number costs most kernels (a few
  // nanoseconds), so that the 250,000 input points of a large grid stay on one thread.
  const unsigned parts = threads_for(n);
  std::vector<Pass> found(parts, Pass{n, false, {}, box, {}});
  in_parallel(parts, [&](unsigned part) {
    const std::size_t first = n * part / parts, last = n * (part + 1) / parts;
    Pass& pass = found[part];
    constexpr std::size_t block_size = 512;
    for (std::size_t from = first; from < last; from += block_size) {
      const std::size_t to = std::min(last, from + block_size);
      if (block(from, to, pass) != 0 && pass.not_finite == n) {
        for (std::size_t k = from; k < to && pass.not_finite == n; ++k) {
          const Point2 p = out[k];
          if (!std::isfinite(p.x) || !std::isfinite(p.y)) pass.not_finite = k;
        }
      }
    }
  });
  // Several parts only for many more points than parts: none is empty, each has its box.
  Pass all = found[0];
  for (const Pass& pass : found) {
    all.not_finite = std::min(all.not_finite, pass.not_finite);
    all.behind = all.behind || pass.behind;
    all.about_eye.add(pass.about_eye);
    all.points.add(pass.points);
    all.low = {std::min(all.low.x, pass.low.x), std::min(all.low.y, pass.low.y)};
    all.high = {std::max(all.high.x, pass.high.x), std::max(all.high.y, pass.high.y)};
  }
  return all;
}

// The box of points four at a time, each lane a box of its own (Box3::add's comparisons).
struct PointBox {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3Lanes lo{{inf, inf, inf, inf}, {inf, inf, inf, inf}, {inf, inf, inf, inf}};
  Vec3Lanes hi{-lo.x, -lo.x, -lo.x};
  [[gnu::always_inline]] void add(const Vec3Lanes& v) {
    lower(lo.x, v.x), lower(lo.y, v.y), lower(lo.z, v.z);
    raise(hi.x, v.x), raise(hi.y, v.y), raise(hi.z, v.z);
  }
  void into(Box3& box) const {
    for (int l = 0; l < 4; ++l)
      box.add(Box3{{lo.x[l], lo.y[l], lo.z[l]}, {hi.x[l], hi.y[l], hi.z[l]}});
  }
};

// What a pass keeps of images made four at a time, lane by lane: their box and x * 0 summed.
struct ImageLanes {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  Lanes low[2] = {{inf, inf, inf, inf}, {inf, inf, inf, inf}};
  Lanes high[2] = {-low[0], -low[0]};
  Lanes seen_x = {}, seen_y = {};
  // Stores the images of four points at `out`, `stride` doubles apart, and keeps them.
  [[gnu::always_inline]] void put(const Lanes& x, const Lanes& y, double* out, std::size_t stride) {
    for (int l = 0; l < 4; ++l) out[stride * l] = x[l], out[stride * l + 1] = y[l];
    seen_x += x * 0.0;
    seen_y += y * 0.0;
    lower(low[0], x), lower(low[1], y), raise(high[0], x), raise(high[1], y);
  }
  // Adds the lanes' box to the pass's and returns their sum of x * 0.
  [[gnu::always_inline]] double into(Pass& pass) const {
    double seen = 0;
    for (int l = 0; l < 4; ++l) {
      pass.low = {std::min(pass.low.x, low[0][l]), std::min(pass.low.y, low[1][l])};
      pass.high = {std::max(pass.high.x, high[0][l]), std::max(pass.high.y, high[1][l])};
      seen += seen_x[l] + seen_y[l];
    }
    return seen;
  }
};

// One point's image, stored at `out` and kept by the pass: returns its x * 0 + y * 0.
inline double put_image(Point2 p, double* out, Pass& pass) {
  p.store(out);
  pass.low = {std::min(pass.low.x, p.x), std::min(pass.low.y, p.y)};
  pass.high = {std::max(pass.high.x, p.x), std::max(pass.high.y, p.y)};
  return p.x * 0.0 + p.y * 0.0;
}

// The images of n points, `in_stride` doubles apart, into `out`, `out_stride` apart:
// `image(x, y, z, X, Y)` makes X and Y of x, y and z, numbers or vector lanes (processor.h) alike,
// so that four points at a time have the images one at a time gives them, bit for bit. Returns the
// sum of x * 0 of the images.
template <class Image>
[[gnu::always_inline]] inline double block_body(Image&& image, const double* in,
                                                std::size_t in_stride, std::size_t n, double* out,
                                                std::size_t out_stride, Pass& pass) {
  const std::size_t s = in_stride, t = out_stride;
  double seen = 0;
  std::size_t k = 0;
  if (n >= 4) {
    ImageLanes images;
    PointBox box;
    for (; k + 4 <= n; k += 4) {
      const Vec3Lanes v = load_lanes(in + s * k, s);
      if (pass.box) box.add(v);
      Lanes x, y;
      image(v.x, v.y, v.z, x, y);
      images.put(x, y, out + t * k, t);
    }
    if (pass.box) box.into(pass.points);
    seen = images.into(pass);
  }
  for (; k < n; ++k) {
    const double* p = in + s * k;
    if (pass.box) pass.points.add(Vec3::load(p));
    double x, y;
    image(p[0], p[1], p[2], x, y);
    seen += put_image({x, y}, out + t * k, pass);
  }
  return seen;
}

template <class Image>
double parallel_block_base(const Image& image, const double* in, std::size_t in_stride,
                           std::size_t n, double* out, std::size_t out_stride, Pass& pass) {
  return block_body(image, in, in_stride, n, out, out_stride, pass);
}

#if IGDS_X86
template <class Image>
__attribute__((target("avx2"))) double parallel_block_avx2(const Image& image, const double* in,
                                                           std::size_t in_stride, std::size_t n,
                                                           double* out, std::size_t out_stride,
                                                           Pass& pass) {
  return block_body(image, in, in_stride, n, out, out_stride, pass);
}
#endif

// each_block for a parallel projection.
template <class Image>
Pass each_point(Vec3View in, MutablePoint2View out, const Image& image, bool box) {
  auto block = parallel_block_base<Image>;
#if IGDS_X86
  if (best_kernels()) block = parallel_block_avx2<Image>;
#endif
  return each_block(
      in, out,
      [&](std::size_t from, std::size_t to, Pass& pass) {
        return block(image, in.data() + in.stride() * from, in.stride(), to - from,
                     out.data() + out.stride() * from, out.stride(), pass);
      },
      box);
}

// CONIC's images of n points (ConicImages, conic_lanes.h) by block_body, and what they find (a
// point not in front of the eye, the box about it) kept in the pass.
struct ConicBlock {
  const ConicFrame* f;
  Vec3 eye;
  std::size_t in_stride, out_stride;
};
[[gnu::always_inline]] inline double conic_block_body(const ConicBlock& c, const double* in,
                                                      std::size_t n, double* out, Pass& pass) {
  ConicImages conic(*c.f, c.eye);
  const double seen = block_body(conic, in, c.in_stride, n, out, c.out_stride, pass);
  conic.finish();
  pass.behind = pass.behind || conic.behind;
  pass.about_eye.add(conic.about_eye);
  return seen;
}

double conic_block_base(const ConicBlock& c, const double* in, std::size_t n, double* out,
                        Pass& pass) {
  return conic_block_body(c, in, n, out, pass);
}

#if IGDS_X86
__attribute__((target("avx2"))) double conic_block_avx2(const ConicBlock& c, const double* in,
                                                        std::size_t n, double* out, Pass& pass) {
  return conic_block_body(c, in, n, out, pass);
}
#endif

}  // namespace

ConicFrame conic_frame(Vec3 view, Vec3 centre) {
  const Vec3 axis = centre - view;
  const double distance = norm(axis);
  if (!std::isfinite(distance)) refuse(DataError::Problem::projection_parameters);
  if (!(distance > 0)) refuse(DataError::Problem::view_at_centre);
  const Vec3 w = unit(axis);
  Vec3 side = cross(w, Vec3{0, 0, 1});
  if (norm(side) < 1e-6) side = cross(w, Vec3{0, 1, 0});
  const Vec3 r = unit(side);
  return {w, r, cross(r, w), distance};
}

bool isom_parameters_valid(double axis, double angle_degrees) {
  return (axis == 1 || axis == 2 || axis == 3) && angle_degrees >= 0 && angle_degrees <= 90;
}

bool asson_parameters_valid(std::array<double, 3> a) {
  for (double angle : a) {
    if (!(angle > 90 && angle < 180)) return false;
  }
  return std::abs(a[0] + a[1] + a[2] - 360) <= 1e-9;
}

bool view_parameters_valid(const View& view) {
  const auto& p = view.parameters;
  switch (view.projection) {
    case Projection::conic:
      return finite({p[0], p[1], p[2]});
    case Projection::assonometric:
      return asson_parameters_valid(p);
    case Projection::isometric:
      return isom_parameters_valid(p[0], p[1]);
    case Projection::orthogonal:
      return p[0] == 1 || p[0] == 2 || p[0] == 3;
  }
  return false;
}

namespace {

Pass orthog_pass(Vec3View in, int plane, MutablePoint2View out, bool box = false) {
  check_sizes(in, out);
  // DESIM[3] numbering of the manual: 1 XY, 2 XZ, 3 YZ.
  switch (plane) {
    case 1:
      return each_point(
          in, out,
          [](const auto& x, const auto& y, const auto&, auto& X, auto& Y) { X = x, Y = y; }, box);
    case 2:
      return each_point(
          in, out,
          [](const auto& x, const auto&, const auto& z, auto& X, auto& Y) { X = x, Y = z; }, box);
    case 3:
      return each_point(
          in, out,
          [](const auto&, const auto& y, const auto& z, auto& X, auto& Y) { X = y, Y = z; }, box);
    default:
      refuse(DataError::Problem::projection_parameters);
  }
}

Pass isom_pass(Vec3View in, int axis, double angle_degrees, MutablePoint2View out,
               bool box = false) {
  check_sizes(in, out);
  if (!isom_parameters_valid(axis, angle_degrees))
    refuse(DataError::Problem::projection_parameters);
  // docs/kernels.md: the two kept coordinates r1, r2 in x y z order, the dropped one d drawn
  // obliquely.
  const double c = std::cos(angle_degrees * degree), s = std::sin(angle_degrees * degree);
  return each_point(
      in, out,
      [axis, c, s](const auto& x, const auto& y, const auto& z, auto& X, auto& Y) {
        const auto& r1 = axis == 1 ? y : x;
        const auto& r2 = axis == 3 ? y : z;
        const auto& d = axis == 1 ? x : axis == 2 ? y : z;
        X = r1 + d * c, Y = r2 + d * s;
      },
      box);
}

Pass conic_pass(Vec3View in, Vec3 view, Vec3 centre, MutablePoint2View out, bool box = false) {
  check_sizes(in, out);
  if (!finite(view)) refuse(DataError::Problem::projection_parameters);
  const ConicFrame f = conic_frame(view, centre);
  auto block = conic_block_base;
#if IGDS_X86
  if (best_kernels()) block = conic_block_avx2;
#endif
  return each_block(
      in, out,
      [&](std::size_t from, std::size_t to, Pass& pass) {
        return block({&f, view, in.stride(), out.stride()}, in.data() + in.stride() * from,
                     to - from, out.data() + out.stride() * from, pass);
      },
      box);
}

Pass matrix_pass(Vec3View in, const AssonMatrix& a, MutablePoint2View out, bool box = false) {
  return each_point(
      in, out,
      [&a](const auto& x, const auto& y, const auto& z, auto& X, auto& Y) {
        X = a.xx * x + a.xy * y, Y = a.yx * x + a.yy * y + a.yz * z;
      },
      box);
}

Pass asson_pass(Vec3View in, std::array<double, 3> angles_degrees, MutablePoint2View out,
                bool box = false) {
  check_sizes(in, out);
  if (!asson_parameters_valid(angles_degrees)) refuse(DataError::Problem::projection_parameters);
  return matrix_pass(in, asson_matrix(angles_degrees), out, box);
}

Pass project_pass(const View& view, Vec3 centre, Vec3View in, MutablePoint2View out,
                  bool box = false) {
  const auto& p = view.parameters;
  // Checked before the plane or axis becomes an integer: a number beyond an int's range is none.
  if (!view_parameters_valid(view)) refuse(DataError::Problem::projection_parameters);
  switch (view.projection) {
    case Projection::conic:
      return conic_pass(in, {p[0], p[1], p[2]}, centre, out, box);
    case Projection::isometric:
      return isom_pass(in, static_cast<int>(p[0]), p[1], out, box);
    case Projection::assonometric:
      return asson_pass(in, p, out, box);
    case Projection::orthogonal:
      return orthog_pass(in, static_cast<int>(p[0]), out, box);
  }
  refuse(DataError::Problem::projection_parameters);
}

}  // namespace

void project(const View& view, Vec3 centre, Vec3View in, MutablePoint2View out) {
  const auto& p = view.parameters;
  if (view.projection == Projection::conic && view_parameters_valid(view))
    return conic(in, {p[0], p[1], p[2]}, centre, out);
  project_pass(view, centre, in, out);
}

ProjectedImage project_image(const View& view, Vec3 centre, Vec3View in, MutablePoint2View out,
                             bool box_of_points) {
  const auto& p = view.parameters;
  const Vec3 eye{p[0], p[1], p[2]};
  const bool conic = view.projection == Projection::conic && view_parameters_valid(view);
  // A view point at the centre has no frame: it is refused as inside the box when it is.
  if (conic && eye.x == centre.x && eye.y == centre.y && eye.z == centre.z &&
      inside_bounding_box(in, eye))
    refuse(DataError::Problem::view_inside_box);
  const Pass pass = project_pass(view, centre, in, out, box_of_points);
  // The box about the eye holds 0 on every axis: the eye is in the box (the sign of p - eye is
  // that of the comparison of p with the eye).
  if (conic && pass.about_eye.contains({})) refuse(DataError::Problem::view_inside_box);
  if (pass.behind) refuse(DataError::Problem::behind_eye);
  return {pass.not_finite, {pass.low.x, pass.low.y, pass.high.x, pass.high.y}, pass.points};
}

ProjectedPart project_part(const View& view, Vec3 centre, Vec3View in, MutablePoint2View out) {
  const Pass pass = project_pass(view, centre, in, out);
  return {pass.not_finite, pass.behind, pass.about_eye};
}

std::array<double, 3> ProjectiveMap::apply(Vec3 p) const {
  std::array<double, 3> out;
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * p.x + m[i][1] * p.y + m[i][2] * p.z + m[i][3];
  return out;
}

ProjectiveMap projection_map(const View& view, Vec3 centre) {
  if (!view_parameters_valid(view)) refuse(DataError::Problem::projection_parameters);
  ProjectiveMap map;
  map.m[2][3] = 1;  // h = 1 for the parallel projections
  const auto& p = view.parameters;
  auto row = [&map](int i, double x, double y, double z, double c) {
    map.m[i][0] = x, map.m[i][1] = y, map.m[i][2] = z, map.m[i][3] = c;
  };
  switch (view.projection) {
    case Projection::orthogonal: {
      const int plane = static_cast<int>(p[0]);
      row(0, plane == 3 ? 0 : 1, plane == 3 ? 1 : 0, 0, 0);
      row(1, 0, plane == 1 ? 1 : 0, plane == 1 ? 0 : 1, 0);
      break;
    }
    case Projection::isometric: {
      const int axis = static_cast<int>(p[0]);
      const double c = std::cos(p[1] * degree), s = std::sin(p[1] * degree);
      // X = r1 + d cos a, Y = r2 + d sin a, r1 r2 the kept coordinates in x y z order.
      if (axis == 1) row(0, c, 1, 0, 0), row(1, s, 0, 1, 0);
      if (axis == 2) row(0, 1, c, 0, 0), row(1, 0, s, 1, 0);
      if (axis == 3) row(0, 1, 0, c, 0), row(1, 0, 1, s, 0);
      break;
    }
    case Projection::assonometric: {
      const AssonMatrix a = asson_matrix(p);
      row(0, a.xx, a.xy, 0, 0);
      row(1, a.yx, a.yy, a.yz, 0);
      break;
    }
    case Projection::conic: {
      const Vec3 eye{p[0], p[1], p[2]};
      const ConicFrame f = conic_frame(eye, centre);
      // X = D (P-V).r / (P-V).w: with h = (P-V).w / D, X h = (P-V).r and Y h = (P-V).t.
      row(0, f.r.x, f.r.y, f.r.z, -dot(eye, f.r));
      row(1, f.t.x, f.t.y, f.t.z, -dot(eye, f.t));
      const double d = 1 / f.distance;
      row(2, d * f.w.x, d * f.w.y, d * f.w.z, -d * dot(eye, f.w));
      map.perspective = true;
      break;
    }
  }
  return map;
}

void orthog(Vec3View in, int plane, MutablePoint2View out) {
  orthog_pass(in, plane, out);
}

void isom(Vec3View in, int axis, double angle_degrees, MutablePoint2View out) {
  isom_pass(in, axis, angle_degrees, out);
}

void conic(Vec3View in, Vec3 view, Vec3 centre, MutablePoint2View out) {
  check_sizes(in, out);
  if (!finite(view)) refuse(DataError::Problem::projection_parameters);
  const ConicFrame f = conic_frame(view, centre);
  // Refuse before writing anything: a point behind the eye has no image.
  for (const Vec3& p : in) {
    if (!(dot(p - view, f.w) > 0)) refuse(DataError::Problem::behind_eye);
  }
  conic_pass(in, view, centre, out);
}

void asson(Vec3View in, std::array<double, 3> angles_degrees, MutablePoint2View out) {
  asson_pass(in, angles_degrees, out);
}

void prospar(Vec3View in, std::array<double, 2> angles_degrees, MutablePoint2View out) {
  check_sizes(in, out);
  if (!std::isfinite(angles_degrees[0]) || !std::isfinite(angles_degrees[1]))
    refuse(DataError::Problem::projection_parameters);
  matrix_pass(in,
              prospar_matrix((angles_degrees[0] + 90) * degree, (angles_degrees[1] + 90) * degree),
              out);
}

namespace {

// Four points at a time (PointBox), then the points left over one at a time. (The same box;
// where its side is a zero met with both signs, the sign kept may be the other.)
[[gnu::always_inline]] inline Box3 box_body(Vec3View points) {
  const double* p = points.data();
  const std::size_t s = points.stride(), n = points.size();
  PointBox lanes;
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) lanes.add(load_lanes(p + s * k, s));
  Box3 box;
  lanes.into(box);
  for (; k < n; ++k) box.add(points[k]);
  return box;
}

Box3 box_base(Vec3View points) {
  return box_body(points);
}

#if IGDS_X86
__attribute__((target("avx2"))) Box3 box_avx2(Vec3View points) {
  return box_body(points);
}
#endif

}  // namespace

Box3 bounding_box(Vec3View points) {
#if IGDS_X86
  if (best_kernels()) return box_avx2(points);
#endif
  return box_base(points);
}

Vec3 bounding_box_centre(Vec3View points) {
  const Box3 box = bounding_box(points);
  return box.empty() ? Vec3{} : box.centre();
}

bool inside_bounding_box(Vec3View points, Vec3 p) {
  return bounding_box(points).contains(p);
}

}  // namespace igds
