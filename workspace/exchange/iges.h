// IGES 5.3 for today's CAD systems: the interpolated surface as exact bicubic B-spline surfaces
// (entity 128) and the input curves and stringers as B-spline curves (entity 126), in the fixed
// 80-column format (S, G, D, P and T sections). docs/exchange.md gives the choices.
#pragma once

#include <cstddef>
#include <string>

#include "workspace/exchange/dates.h"
#include "workspace/kernels/surface.h"
#include "workspace/text_out.h"

namespace igds {

// The length unit a CAD file declares (IGES G14 and G15, STEP's length unit). IGDS's numbers have
// none: `none` says so (docs/exchange.md, "Units"), the others are the user's choice.
enum class LengthUnit { mm, cm, m, inch, foot, none };

// What a CAD file says besides the geometry (IGES and STEP).
struct CadHeader {
  std::string name;          // the surface's name (IGES G3, G12; STEP's product)
  std::string file_name;     // e.g. HULL.IGS (IGES G4; STEP FILE_NAME)
  Timestamp date;            // IGES G18, G25; STEP FILE_NAME
  std::string author;        // empty: unknown (IGES G21)
  std::string organization;  // empty: unknown (IGES G22)
  LengthUnit unit = LengthUnit::mm;
};

// The declared resolution (IGES G19, STEP's length uncertainty): 1e-12 of the largest coordinate
// (of 1 when all are smaller), in the file's numbers (docs/exchange.md, "Units").
double cad_resolution(double largest);

// How the surface is written: one entity 128 for the whole surface (the default), whose interior
// knots have multiplicity 3 because the surface is only C0 across patch borders (docs/exchange.md,
// "IGES 5.3"), which readers report (OpenCASCADE: "Resulting Geom_Surface is C0-continuous"); or
// one entity 128 per patch (EXPORT's FACES: each a bicubic Bézier patch, smooth inside,
// neighbours sharing their border controls bit for bit).
enum class SurfaceForm { patches, one };

// The file: the surface entities first (labelled SURFACE, or PATCH with subscript the patch
// number, row by row from 1), then input curves 1..NOCUR and stringers 1..NOSTR as entity 126
// (labelled CURVE and STRINGER, subscript the number), then one group of those curves (entity 402
// form 7, labelled CURVES). Surface parameters: u along the curves
// from 0 to NOSTR-1, v along the stringers from 0 to NOCUR-1, patch (i, j) on [j, j+1] x
// [i, i+1] with its own parameters u - j, v - i, in both forms: INTPN row I, column J is at
// u = j + a/(INTST+1), v = i + b/(INTCU+1) (docs/exchange.md, "A surface, exactly"). The curves
// are in the splines' own parameter, the running chord length (0 at the first point, the sum of the
// chords |P_k+1 - P_k| at point k+1), in which they are C2: cubic B-splines with every inner knot
// once. A curve whose points all coincide (a pole) is a point and is left out. Units: the header's.
// Throws DataError (shape) when PATCHES does not have the shape of `input`, (patch_not_finite)
// for a patch that is not finite, (too_many_points) when a section would need more than 9,999,999
// lines.
std::string write_iges(const SurfaceInput& input, const Array& patches, const CadHeader& header,
                       SurfaceForm form = SurfaceForm::one);
// The same into `out`, made while it is written (the file may be hundreds of megabytes).
void write_iges(const SurfaceInput& input, const Array& patches, const CadHeader& header,
                TextOut& out, SurfaceForm form = SurfaceForm::one);

}  // namespace igds
