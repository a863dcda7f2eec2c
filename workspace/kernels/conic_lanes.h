// CONIC's images four points at a time (processor.h) or one at a time, the same numbers either
// way, for the projections (project.cpp) and for the kernels that make their points as they go
// (the combs' ends, curvature.cpp): docs/kernels.md, "Projections".
#pragma once

#include <limits>

#include "workspace/kernels/processor.h"
#include "workspace/kernels/vec3.h"

namespace igds {

// CONIC's frame (docs/kernels.md): w towards the centre, r to the right of it, t up, z vertical on
// the screen; D the distance from the eye to the centre.
struct ConicFrame {
  Vec3 w, r, t;
  double distance;
};
// Throws DataError for a view point that is not finite or at the centre.
ConicFrame conic_frame(Vec3 view, Vec3 centre);

// The images of points seen from `eye`, X = D (q.r) / (q.w) and Y = D (q.t) / (q.w) with
// q = p - eye, and what they find: whether a point is not in front of the eye (q.w not above 0)
// and the box of the points about the eye (the q). Each lane does the operations of a point at a
// time (of a Vec3), in its order; numbers and lanes take the same arguments (kernels/project.cpp's
// block_body).
struct ConicImages {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  ConicImages(const ConicFrame& frame, Vec3 view) : f(&frame), eye(view) {}
  const ConicFrame* f;
  Vec3 eye;
  Lanes low[3] = {{inf, inf, inf, inf}, {inf, inf, inf, inf}, {inf, inf, inf, inf}};
  Lanes high[3] = {-low[0], -low[0], -low[0]};
  LaneMask ahead = ~LaneMask{};
  bool behind = false;
  Box3 about_eye;

  [[gnu::always_inline]] inline void operator()(const Lanes& x, const Lanes& y, const Lanes& z,
                                                Lanes& X, Lanes& Y) {
    const Lanes q[3] = {x - eye.x, y - eye.y, z - eye.z};
    const Lanes depth = q[0] * f->w.x + q[1] * f->w.y + q[2] * f->w.z;
    ahead &= depth > 0;
    for (int d = 0; d < 3; ++d) lower(low[d], q[d]), raise(high[d], q[d]);
    X = f->distance * (q[0] * f->r.x + q[1] * f->r.y + q[2] * f->r.z) / depth;
    Y = f->distance * (q[0] * f->t.x + q[1] * f->t.y + q[2] * f->t.z) / depth;
  }
  Point2 operator()(Vec3 p) {
    const Vec3 q = p - eye;
    const double depth = dot(q, f->w);
    if (!(depth > 0)) behind = true;
    about_eye.add(q);
    return {f->distance * dot(q, f->r) / depth, f->distance * dot(q, f->t) / depth};
  }
  void operator()(double x, double y, double z, double& X, double& Y) {
    const Point2 p = (*this)(Vec3{x, y, z});
    X = p.x, Y = p.y;
  }
  // The lanes' findings added to `behind` and `about_eye`.
  void finish() {
    for (int l = 0; l < 4; ++l) {
      behind = behind || ahead[l] == 0;
      about_eye.add(Box3{{low[0][l], low[1][l], low[2][l]}, {high[0][l], high[1][l], high[2][l]}});
    }
    ahead = ~LaneMask{};
  }
};

}  // namespace igds
