// A B-spline surface from a CAD file, for IMPORT: the first bicubic-or-other B-spline surface of an
// IGES 5.3 file (entity 128) or a STEP file (B_SPLINE_SURFACE_WITH_KNOTS, rational or not), every
// count and size checked against the file before it is used, and the surface evaluated with its
// first derivatives. docs/exchange.md, "A CAD surface in", gives the choices.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/kernels/vec3.h"

namespace igds {

// What a CAD file's surface is: degrees, knot vectors written out (each knot as often as its
// multiplicity), controls with the u index varying fastest, weights (empty: polynomial), and the
// parameter range it is used on.
struct CadSurface {
  int degree_u = 0, degree_v = 0;
  std::size_t count_u = 0, count_v = 0;  // controls along u and along v
  std::vector<double> knots_u, knots_v;  // count + degree + 1 each
  std::vector<Vec3> controls;            // count_u * count_v, control (a, b) at b * count_u + a
  std::vector<double> weights;           // empty, or one per control, all > 0
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

// A file that is not what it should be: the reason, in capitals, for the report
// (`LINE 12: ENTITY 128 PROMISES 10000 CONTROLS, THE FILE HOLDS 20`).
struct CadReadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The most controls IMPORT reads: the four million points of igds's largest grids, and more.
inline constexpr std::size_t cad_max_controls = 16'000'000;

// The first entity 128 of an IGES file's text. Throws CadReadError.
CadSurface read_iges_surface(std::string_view text);
// The first B_SPLINE_SURFACE_WITH_KNOTS of a STEP file's text (a complex instance with
// RATIONAL_B_SPLINE_SURFACE for a rational one). Throws CadReadError.
CadSurface read_step_surface(std::string_view text);

// The surface at (u, v) (clamped to its range) and its first derivatives by u and v.
struct SurfacePoint {
  Vec3 p, du, dv;
};
SurfacePoint evaluate(const CadSurface& s, double u, double v);

}  // namespace igds
