// The images of DISPLAY INPUT and DISPLAY SURFACE (manual 4.4): the input points or the
// interpolated grid of a surface, projected as a view says. The commands make them; the session
// makes them again at start from the surface they were drawn from (Image::drawn_from), so the
// same function makes both, bit for bit.
#pragma once

#include "workspace/kernels/project.h"
#include "workspace/state.h"

namespace igds {

// DISPLAY INPUT: INPPN projected (NOCUR x NOSTR x 2) and an arrow for every non-zero border
// tangent (Image::arrows). DISPLAY SURFACE: INTPN projected. Both throw DataError
// (view_inside_box for a view point inside the points' bounding box, behind_eye, ...).
Image input_image(const Workspace& ws, const View& view);
Image surface_image(const Workspace& ws, const View& view);

// The image `desim` describes (DESIM[1] 0 input, 1 surface) of the surface of `ws`.
Image image_of(const Workspace& ws, const Description& desim);

}  // namespace igds
