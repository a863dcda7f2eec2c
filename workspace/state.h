// The IGDS workspace variables (manual section 7, spec igds.md section 4): the whole session.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "workspace/kernels/array.h"
#include "workspace/kernels/project.h"

namespace igds {

// DESIM: what an image shows and how it was projected.
struct Description {
  int what = 0;                                    // DESIM[1]: 0 input points, 1 surface
  Projection projection = Projection::orthogonal;  // DESIM[2]
  std::array<double, 3> parameters{};  // DESIM[3 4 5]: view point, angles, axis+angle, plane
  friend bool operator==(const Description&, const Description&) = default;
};

// A projected image: IMAGE with its DESIM (or TEMP1/DEST1, TEMP2/DEST2).
struct Image {
  Description desim;
  // IMAGE: planes x rows x 2, one plane per curve: NOCUR x NOSTR x 2 for an input image, the
  // shape of INTPN with 2 columns for a surface image.
  Array points;
  // Input images only: one row per non-zero border tangent, k x 6: the projected base point (x y)
  // and the projected tangent vector (dx dy), in the units of `points`, then the point number
  // and 1 (along the curve) or 0 (along the stringer). Drawn as arrows. (Files written before the
  // last two columns existed have k x 4.)
  Array arrows;
  friend bool operator==(const Image&, const Image&) = default;
};

// An image never changes once made: the workspace shares it (STORE FIRST keeps the same image,
// the screen and the drawing read its points without a copy).
using ImageRef = std::shared_ptr<const Image>;

// The same images, or equal ones.
inline bool same_image(const ImageRef& a, const ImageRef& b) {
  return a == b || (a && b && *a == *b);
}

struct Workspace {
  int nocur = 0, nostr = 0;  // NOCUR, NOSTR: input curves and stringers (0: no input yet)
  int intcu = 0, intst = 0;  // INTCU, INTST: curves/stringers interpolated between input ones
  Array inppn;               // INPPN: (NOCUR*NOSTR) x 3, in point-number order
  // INPTG: 2(NOCUR+NOSTR) x 4 border tangents x y z and point number. Rows in this order: the
  // tangents along the curves at the ends of each curve (curve 1 place 1, curve 1 place NOSTR,
  // curve 2 place 1, ...), then the tangents along the stringers at the ends of each stringer
  // (stringer 1 curve 1, stringer 1 curve NOCUR, stringer 2 curve 1, ...). Corners appear twice.
  Array inptg;
  Array patches;   // PATCHES: (NOCUR-1) x (NOSTR-1) x 3 x 4 x 4
  Array intpn;     // INTPN: (NOCUR+INTCU(NOCUR-1)) x (NOSTR+INTST(NOSTR-1)) x 3
  ImageRef image;  // IMAGE / DESIM: the current image
  ImageRef temp1;  // TEMP1 / DEST1: STORE FIRST
  ImageRef temp2;  // TEMP2 / DEST2: STORE SECOND
  // STATUS[1] = 1 for HELP LONG, 0 for SHORT; STATUS[2] = keyboard of the last PLOT
  // (0 none yet, 1 SELECTRIC, 2 EBCDIC); the others are reserved.
  std::array<int, 10> status{1, 0, 0, 0, 0, 0, 0, 0, 0, 0};

  bool has_input() const { return nocur > 0; }
  bool has_surface() const { return !intpn.empty(); }
  friend bool operator==(const Workspace& a, const Workspace& b) {
    return a.nocur == b.nocur && a.nostr == b.nostr && a.intcu == b.intcu && a.intst == b.intst &&
           a.inppn == b.inppn && a.inptg == b.inptg && a.patches == b.patches &&
           a.intpn == b.intpn && same_image(a.image, b.image) && same_image(a.temp1, b.temp1) &&
           same_image(a.temp2, b.temp2) && a.status == b.status;
  }
};

}  // namespace igds
