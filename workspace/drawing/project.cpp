#include "workspace/drawing/project.h"

#include <algorithm>
#include <cmath>

#include "workspace/kernels/data_error.h"

namespace igds {

namespace {

// A projected point, refused when it is not in front of the eye.
Point2 image_of(const ProjectiveMap& map, Vec3 p, double* h = nullptr) {
  const auto q = map.apply(p);
  if (!(q[2] > 0)) throw DataError(DataError::Problem::behind_eye);
  if (h) *h = q[2];
  if (!map.perspective) return {q[0], q[1]};
  return {q[0] / q[2], q[1] / q[2]};
}

}  // namespace

Drawing2 project(const Drawing3& drawing, const View& view, Vec3 centre) {
  const ProjectiveMap map = projection_map(view, centre);
  Drawing2 out;
  std::vector<double> xy, weights;
  for (const auto& item : drawing.items()) {
    const auto points = drawing.points(item);
    switch (item.kind) {
      case Drawing3::Kind::polyline: {
        xy.resize(2 * points.size());
        for (std::size_t k = 0; k < points.size(); ++k) image_of(map, points[k]).store(&xy[2 * k]);
        out.add_polyline(Point2View(xy.data(), points.size()), item.style, item.id, item.closed);
        break;
      }
      case Drawing3::Kind::curve: {
        const auto w = drawing.weights(item);
        xy.resize(2 * points.size());
        weights.assign(points.size(), 1.0);
        for (std::size_t k = 0; k < points.size(); ++k) {
          double h = 1;
          image_of(map, points[k], &h).store(&xy[2 * k]);
          weights[k] = (w.empty() ? 1.0 : w[k]) * h;
        }
        // Parallel projections leave polynomial curves polynomial.
        const bool rational = !w.empty() || map.perspective;
        out.add_curve(item.degree, Point2View(xy.data(), points.size()),
                      rational ? std::span<const double>(weights) : std::span<const double>{},
                      item.style, item.id);
        break;
      }
      case Drawing3::Kind::mark:
        out.add_mark(image_of(map, points[0]), item.shape, item.size, item.style, item.id);
        break;
      case Drawing3::Kind::text:
        out.add_text(image_of(map, points[0]), drawing.text(item), item.size, item.style, item.id);
        break;
    }
  }
  return out;
}

namespace {

template <class P>
Box3 box_of(const Drawing<P>& drawing) {
  Box3 box;
  for (const auto& item : drawing.items())
    for (P point : drawing.points(item)) box.add(in_space(point));
  return box;
}

}  // namespace

Box3 bounding_box(const Drawing3& drawing) {
  return box_of(drawing);
}

Box3 bounding_box(const Drawing2& drawing) {
  return box_of(drawing);
}

}  // namespace igds
