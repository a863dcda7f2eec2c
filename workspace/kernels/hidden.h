// Hidden lines of a grid surface (docs/kernels.md, "Hidden lines"): which parts of its curves
// and stringers the surface itself hides, seen as a projection sees it, to a given resolution.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "workspace/kernels/project.h"
#include "workspace/kernels/vec3.h"

namespace igds {

// How near each point is to the eye as `view` sees it (CONIC looking at `centre`), written to
// `out` (as long as `points`): larger is nearer, and on any plane in space an affine function of
// the projected x y (the parallel projections: the distance along the direction of sight; CONIC:
// 1 / h, h the depth along the line of sight over the distance to the centre).
void nearness(const View& view, Vec3 centre, Vec3View points, std::span<double> out);

// A grid seen in the plane: planes x rows points (x y), and the nearness of each.
struct SeenGrid {
  std::size_t planes = 0, rows = 0;
  const double* xy = nullptr;    // planes x rows x 2
  const double* near = nullptr;  // planes x rows
};

// A visible part of a line of the grid: curve `line` (0 to planes - 1: the points of plane
// `line`) or stringer `line - planes` (row `line - planes` of every plane), from parameter `from`
// to `to` (point k of the line is at k; between them along the segment, in proportion).
struct VisiblePiece {
  std::uint32_t line = 0;
  double from = 0, to = 0;
  friend bool operator==(const VisiblePiece&, const VisiblePiece&) = default;
};

// The raster visibility is decided on: cells of side `cell` over the box x0 y0 x1 y1 of the
// plane (what is shown: nothing outside it can hide anything inside it).
struct Raster {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double cell = 1;
};

// The visible pieces of every curve, then every stringer, in order along each line. The
// surface is the grid's quadrilaterals, each two triangles; a point of a line is hidden when a
// triangle covering its cell's centre is nearer than it by more than the tolerance
// (docs/kernels.md). A segment with a point that is not finite is not drawn; a part outside the
// raster is visible. Cost: linear in the points and in the raster's cells.
std::vector<VisiblePiece> visible_pieces(const SeenGrid& grid, const Raster& raster);

// The most cells a raster has across its larger side (the 4014's 4096 addresses are fewer).
inline constexpr double max_raster_cells = 4096;

}  // namespace igds
