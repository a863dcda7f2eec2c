// The generic layer between a drawing and a device (docs/devices.md, steps 2 and 3): one scale
// that keeps the aspect, curves flattened and marks made into strokes in device units, clipping
// in floating point before rounding. Encoders (tek4013, hpgl, svg) only see integer device points.
#pragma once

#include <string>
#include <vector>

#include "devices/device.h"
#include "workspace/drawing/drawing.h"

namespace igds {

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Drawing units to device units: one scale for x and y.
struct Placement {
  double scale = 1, dx = 0, dy = 0;
  Point2 apply(Point2 p) const { return {dx + scale * p.x, dy + scale * p.y}; }
};

// The bounding box of the finite points of a drawing: polyline points, curve control points,
// marks and texts (x0 > x1 when there are none). A shared pool's points are not read when the
// pool came with its box and items of consecutive points cover all of it: the box is theirs.
Box bounds(const Drawing2& drawing);

// The placement that fits `drawing` into `box`, centred, aspect kept, leaving `mark` device units
// on every side for its marks, if it has any. A drawing of one point goes to the box's centre.
Placement fit(const Drawing2& drawing, const Box& box, double mark);
// The same for a drawing whose bounds are `extent` (bounds() of it) and that has marks or not:
// for a caller that needs the bounds too, so that a large drawing is measured once.
Placement fit(const Box& extent, bool marks, const Box& box, double mark);
bool has_marks(const Drawing2& drawing);

// Clips the segment a-b to `clip` (Liang-Barsky); false when nothing of it is inside.
bool clip_segment(Point2& a, Point2& b, const Box& clip);

// How a device measures. Marks and the flattening tolerance are given in points of the 4013
// screen (1024 across, about 0.2 mm on the tube); `point` is one such point in device units.
struct Rendering {
  double point = 1;
  double tolerance = 0.2;  // in 4013 points: how far a flattened curve may stray
  // The texts' room: a text is cut to the characters, `char_width` device units each, that end
  // at `text_right` or before it (docs/devices.md, "Texts"); 0: never cut.
  double char_width = 0;
  double text_right = 0;
};

struct PlacedText {
  DevicePoint at;
  std::string text;
  Style style;
};
// A drawing in integer device units.
struct Placed {
  PathParts paths;                // polylines, flattened curves and marks, in drawing order
  std::vector<Style> styles;      // the style of each path
  std::vector<PlacedText> texts;  // texts whose place lies inside the clip box
  bool clipped = false;           // something lay outside the clip box
  bool texts_cut = false;         // a text was longer than its room (Rendering::text_right)
  DeviceBox box;                  // of every path's points
};

// The drawing placed by `at` and clipped to `clip`, then rounded to the nearest unit (halves
// up); repeated points and paths of fewer than two points are dropped (a dot mark is a path of
// one point repeated: it keeps two).
Placed place(const Drawing2& drawing, const Placement& at, const Box& clip,
             const Rendering& rendering);

// The same, drawn on `device` as it is placed, in drawing order, texts after the lines (no list
// of every path is kept). Returns true when something was clipped; `texts_cut`, when given, says
// whether a text was cut.
bool render(const Drawing2& drawing, const Placement& at, const Box& clip,
            const Rendering& rendering, Device& device, bool* texts_cut = nullptr);

}  // namespace igds
