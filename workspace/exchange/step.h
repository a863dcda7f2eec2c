// STEP (ISO 10303-21, AP214 "automotive design") for today's CAD systems: the same geometry as
// the IGES file (iges.h), as B_SPLINE_SURFACE_WITH_KNOTS and B_SPLINE_CURVE_WITH_KNOTS in the
// GEOMETRIC_SET of a GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION, inside the smallest
// product structure a reader maps to a part. docs/exchange.md gives the choices.
#pragma once

#include <string>

#include "workspace/exchange/iges.h"
#include "workspace/kernels/surface.h"
#include "workspace/text_out.h"

namespace igds {

// The surface (named SURFACE, or PATCH k) in a GEOMETRIC_SET and the curves (CURVE i, STRINGER j)
// in a GEOMETRIC_CURVE_SET named 'input curves', with the parameters, knots and controls of
// write_iges; every control point of the net is one CARTESIAN_POINT that neighbouring patches
// share. Units the header's, uncertainty cad_resolution (none with no unit: it needs one).
// Throws DataError as write_iges does (but for the line limit: STEP has none).
std::string write_step(const SurfaceInput& input, const Array& patches, const CadHeader& header,
                       SurfaceForm form = SurfaceForm::one);
// The same into `text`, made while it is written (the file may be hundreds of megabytes).
void write_step(const SurfaceInput& input, const Array& patches, const CadHeader& header,
                TextOut& text, SurfaceForm form = SurfaceForm::one);

}  // namespace igds
