// Marks 1970 (docs/marks.md; CADA/REM/SUBROUTS's HORTANV, VERTANV and TWISTV): the tangents and
// twists of a grid estimated from its points alone, per unit of the patch parameter.
#pragma once

#include <span>

#include "workspace/kernels/array.h"
#include "workspace/kernels/coons.h"
#include "workspace/kernels/vec3.h"

namespace igds {

// Marks's tangents per unit of patch parameter at every point of one grid line, into `out` (the
// size of `points`). With P(1..m) the line's distinct points (docs/marks.md):
//   m = 2:  P'(1) = P'(2) = P(2) - P(1);
//   interior points (Forrest's F-mesh): the direction of P(i+1) - P(i-1), the length of the
//           shorter of the two chords (zero when P(i+1) = P(i-1): no direction);
//   ends, m >= 3 (parabolas): P'(1) = 2(P(2) - P(1)) - P'(2), P'(m) = 2(P(m) - P(m-1)) - P'(m-1).
// Runs of equal consecutive points are merged first and every duplicate gets its merged point's
// tangent, as the spline does (docs/kernels.md); a line whose points all coincide (the pole of a
// sphere octant) and a line of one point get zero tangents. O(n), allocates nothing.
void marks_tangents(Vec3View points, std::span<Vec3> out);

// Marks's tangents at every point of a NOCUR x NOSTR grid (point-number order): along the curves
// (the rows, Marks's horizontal) and along the stringers (the columns, Marks's vertical), with
// units per_parameter (coons.h): PATCHES takes them as they are.
GridTangents marks_grid_tangents(int nocur, int nostr, Vec3View points);

// AUTO at TANGENTS?: INPTG (2(NOCUR+NOSTR) x 4, row order and point numbers in column 4 as in
// workspace/state.h) holding Marks's end tangent of every curve and stringer divided by the chord
// of its end arc (the first arc of non-zero length from that end), so that COONS's scaling by that
// chord puts Marks's vector itself into PATCHES. A line whose points all coincide gets zero.
// O(NOCUR + NOSTR) for lines without repeated points.
Array marks_border_tangents(int nocur, int nostr, Vec3View points);

// The same INPTG for tangents already computed at every point (per_parameter ones are divided by
// the chord of the end arc, per_chord ones copied): the border of a surface fitted from a deck
// whose given vectors replace some of Marks's.
Array border_tangents_of(int nocur, int nostr, Vec3View points, const GridTangents& tangents);

// TWISTV: twists per unit of both patch parameters at every point, (NOCUR*NOSTR) x 3 in
// point-number order, by Birkhoff and de Boor (docs/marks.md):
//   P''(i,j) = 1/4 [P(i+1,j+1) + P(i-1,j-1) - P(i+1,j-1) - P(i-1,j+1)].
// A diagonal neighbour off the grid is rebuilt from the two points between it and the centre, and
// the twist is zero when one of those is off the grid too. On a rectangular grid whose points are
// all given that always happens at the border (a neighbour off the grid shares its row or its
// column with one of those two points), so every border point has a zero twist.
Array marks_twists(int nocur, int nostr, Vec3View points);

}  // namespace igds
