// What an IGDS image (IMAGE and DESIM, manual section 7) becomes in a drawing, decided here once:
// DISPLAY INPUT's border, tangent arrows and point marks, DISPLAY SURFACE's curves and stringers,
// and the description written beside them. The devices draw the result without knowing grids.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/drawing/drawing.h"
#include "workspace/state.h"

namespace igds {
class Context;
}

namespace igds {

// DISPLAY INPUT (desim.what == 0): the border of the NOCUR x NOSTR grid as one closed polyline,
// each non-zero border tangent as an arrow (shaft and head, one polyline), the input points as
// square marks, then their numbers as texts (Role::label, index k) beside them. DISPLAY SURFACE:
// one polyline per curve, then one per stringer, reading the image's own points (not copied).
// An IMAGE of a shape other than planes x rows x 2 gives no lines (never a crash); non-finite
// points break a line. DISPLAY HIDDEN (desim.hidden): the visible pieces of the curves, then of
// the stringers (workspace/kernels/hidden.h), each a polyline. DISPLAY COMBS (desim.what == 3): the
// surface's lines, then the combs (one path of hairs and one envelope per curve, then per
// stringer, Role::comb). DISPLAY PICTURE (desim.what == 2): the picture's projected drawing with
// its colours and dashes; the description adds the picture's name after PICTURE, and COLOURS and
// the colours used when there are several (the 4013 draws them alike). A zoomed image
// (Image::window): only what lies inside the window, lines cut at its edges, and the window's
// corners as two one-point polylines (they draw nothing) so that the window is what gets scaled
// to the screen.
Picture picture_of(std::shared_ptr<const Image> image);
Picture picture_of(const ImageRef& image);
Picture picture_of(const Image& image);

// The brief description of DISPLAY: what (INPUT or SURFACE), the projection, its parameters
// (e.g. `SURFACE`, `ASSONOMETRIC`, `110 130 120`); no line longer than `width` characters.
std::vector<std::string> describe(const Description& desim, std::size_t width);

// A one-line description of an image (what, projection, parameters), as the none terminal
// mode prints it: IMAGE: SURFACE, ASSONOMETRIC 110 130 120.
std::string describe_line(const Description& desim);

// The same for an image, saying when it is zoomed: the caption gets a line ZOOMED, the line
// `, ZOOMED TO x0 y0 x1 y1` (the window's corners). The line of a picture has what its caption
// has: `IMAGE: PICTURE HAND, ORTHOGONAL XY, COLOURS 1 2 5`.
std::vector<std::string> image_caption(const Image& image, std::size_t width);
std::string image_line(const Image& image);
inline constexpr std::string_view zoomed_word = "ZOOMED";
// ZOOMED TO x0 y0 x1 y1, the window's corners to five significant digits.
std::string zoom_words(const std::array<double, 4>& window);

// What the caption of DISPLAY COMBS says of its combs: SCALE s (a comb is s times the curvature
// long, in the units of the surface), NO CURVATURE (no line bends) or NO COMBS (an image assigned
// in APL).
std::string comb_words(const Image& image);

// A number as APL writes it, in plain ASCII (a minus sign for APL's high minus).
std::string plain_number(double value);

// After a command that put back another state (UNDO, REDO): when the current image is no longer
// `before`, the screen shows the one that is (a clean page, as ZOOM's), or nothing when there is
// none, so that what is shown is always what LIST IMAGES says is current.
void show_current_image(Context& ctx, const ImageRef& before);

// Arrow of a border tangent: the longest one is this fraction of the image's larger side.
inline constexpr double arrow_fraction = 0.25;

// More input points than this in a picture leave no room for their numbers (the square holds
// about 800 character cells): DISPLAY INPUT writes none, ZOOM shows them.
inline constexpr std::size_t max_numbered_points = 4096;

// A hidden-line image's raster: cells across what is shown (docs/decisions.md, "Hidden lines"):
// the picture's square on a 4014 (12-bit addresses), a 4013 point's quarter.
inline constexpr double hidden_line_cells = 4 * 768;

// An input point's mark: a square of this half side, in 4013 points.
inline constexpr double point_mark = 3;

}  // namespace igds
