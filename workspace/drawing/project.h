// The one way a drawing in space becomes a drawing in the plane: a View (kernels/project.h)
// applied to every item. Polylines, marks and texts move with their points; curves stay exact,
// since under the view's projective map a rational Bézier curve is a rational Bézier curve of the
// same degree whose weights are multiplied by h (for the parallel projections h = 1, so
// polynomial curves stay polynomial). Curves are flattened only by the devices, in device units.
#pragma once

#include "workspace/drawing/drawing.h"
#include "workspace/kernels/project.h"

namespace igds {

// `drawing` seen as `view` says; CONIC looks at `centre`. Throws DataError: projection_parameters,
// view_at_centre, or behind_eye when a point (a curve's control point) is not in front of the eye.
Drawing2 project(const Drawing3& drawing, const View& view, Vec3 centre);

// The bounding box of every point of a drawing (polyline points, curve control points, marks and
// texts); empty when it has none.
Box3 bounding_box(const Drawing3& drawing);
// The same for a drawing in the plane, at z = 0.
Box3 bounding_box(const Drawing2& drawing);

}  // namespace igds
