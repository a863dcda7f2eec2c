// EXPORT SVG: the Tek screen of a DISPLAY as a standalone SVG document.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "devices/device.h"
#include "workspace/drawing/drawing.h"
#include "workspace/text_out.h"

namespace igds {

// A Device that writes SVG elements in the 1024 x 780 space of the 4013, y flipped: the 4013
// point (x, y) is the SVG point (x, 779 - y). Polylines become <polyline>, text <text>. The
// document goes into `out` as it is made (for EXPORT SVG the file being written): the head at
// once, each element when it is complete, the end at finish().
class SvgWriter : public Device {
 public:
  explicit SvgWriter(TextOut& out);
  void move(DevicePoint p) override;
  void draw(DevicePoint p) override;
  // The points written straight into the element (the bulk of a document).
  void polyline(std::span<const DevicePoint> points) override;
  // The bytes of style() and polyline() for each path in turn, a large drawing's made on the
  // cores.
  void paths(const PathParts& paths, std::span<const Style> styles) override;
  void text(DevicePoint p, std::string_view line) override;
  // A new page erases the screen: what was drawn is painted over with the white background
  // (the elements before it are already written).
  void page() override;
  // Pens as colours (1 black, 2 red, 3 green, 4 blue, 5 magenta, 6 cyan, ...), dashes as dash
  // arrays, weight 2 as a wider stroke; attributes only where they differ from the default.
  void style(const Style& style) override;
  // Ends the document; the writer is done with.
  void finish();

 private:
  void close_polyline();
  void start_polyline();  // its element, up to its first point (at_)

  TextOut* out_;
  DevicePoint at_;
  bool at_known_ = false;
  bool drawing_ = false;
  std::string attributes_;  // of the polylines that follow: "" for pen 1, solid, weight 1
  int pen_ = 1;             // of the texts that follow
};

// A standalone SVG of a picture, laid out as on the Tek screen: viewBox in 4013 points,
// polylines, the caption as text; into `out` as it is made, or as a string.
void write_svg(const Picture& picture, TextOut& out);
std::string svg_of(const Picture& picture);

}  // namespace igds
