// The generic layer between an Image and a device (style.md, Devices): what to draw in image
// units, one scale that keeps the aspect, and clipping in floating point before rounding.
#pragma once

#include <string>
#include <vector>

#include "devices/device.h"
#include "workspace/kernels/vec3.h"
#include "workspace/state.h"

namespace igds {

// An image as polylines and marks in image units, with its description.
struct Picture {
  std::vector<std::vector<Point2>> paths;
  std::vector<Point2> marks;             // input points: a small square each, sized in device units
  std::vector<std::string> description;  // one item per line, printable ASCII
};

// DISPLAY INPUT (desim.what == 0): the border of the NOCUR x NOSTR grid as one closed polyline,
// each non-zero border tangent as an arrow (shaft and head, one polyline), the input points as
// marks. DISPLAY SURFACE: one polyline per curve, then one per stringer. An IMAGE of a shape
// other than planes x rows x 2 gives no lines (never a crash); non-finite points break a line.
Picture picture_of(const Image& image);

// The brief description of DISPLAY: what (INPUT or SURFACE), the projection, its parameters
// (e.g. `SURFACE`, `ASSONOMETRIC`, `110 130 120`); no line longer than `width` characters.
std::vector<std::string> describe(const Description& desim, std::size_t width);

// A number as APL writes it, in plain ASCII (a minus sign for APL's high minus).
std::string plain_number(double value);

// The longest description line: the 17 columns of the Tek screen right of the image.
inline constexpr std::size_t description_width = 17;

// Arrow of a border tangent: the longest one is this fraction of the image's larger side.
inline constexpr double arrow_fraction = 0.25;

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Image units to device units: one scale for x and y.
struct Placement {
  double scale = 1, dx = 0, dy = 0;
  Point2 apply(Point2 p) const { return {dx + scale * p.x, dy + scale * p.y}; }
};

// The bounding box of the finite points of the paths and marks (x0 > x1 when there are none).
Box bounds(const Picture& picture);

// The placement that fits `picture` into `box`, centred, aspect kept, leaving `mark` device
// units on every side for its marks, if it has any. A picture of one point goes to the box's
// centre.
Placement fit(const Picture& picture, const Box& box, double mark);

// The picture in integer device units: paths and marks (squares of half side `mark`) placed,
// clipped to `clip` in floating point, then rounded to the nearest unit; repeated points and
// paths of fewer than two points are dropped.
struct Placed {
  std::vector<DevicePath> paths;
  bool clipped = false;  // something lay outside `clip`
};
Placed place(const Picture& picture, const Placement& at, double mark, const Box& clip);

// Clips the segment a-b to `clip` (Liang-Barsky); false when nothing of it is inside.
bool clip_segment(Point2& a, Point2& b, const Box& clip);

}  // namespace igds
