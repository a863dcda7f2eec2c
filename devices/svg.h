// EXPORT SVG: the Tek screen of a DISPLAY as a standalone SVG document.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "devices/device.h"
#include "workspace/drawing/drawing.h"

namespace igds {

// A Device that writes SVG elements in the 1024 x 780 space of the 4013, y flipped: the 4013
// point (x, y) is the SVG point (x, 779 - y). Polylines become <polyline>, text <text>.
class SvgWriter : public Device {
 public:
  SvgWriter();
  void move(DevicePoint p) override;
  void draw(DevicePoint p) override;
  // The points written straight into the element (the bulk of a document).
  void polyline(std::span<const DevicePoint> points) override;
  void text(DevicePoint p, std::string_view line) override;
  void page() override;
  // Pens as colours (1 black, 2 red, 3 green, 4 blue, 5 magenta, 6 cyan, ...), dashes as dash
  // arrays, weight 2 as a wider stroke; attributes only where they differ from the default.
  void style(const Style& style) override;
  // The whole document; the writer is done with.
  std::string document();

 private:
  void close_polyline();
  void start_polyline();  // its element, up to its first point (at_)

  std::string body_;  // the document's head, then the elements so far
  std::size_t head_;  // the head's length
  DevicePoint at_;
  bool at_known_ = false;
  bool drawing_ = false;
  std::string attributes_;  // of the polylines that follow: "" for pen 1, solid, weight 1
};

// A standalone SVG of a picture, laid out as on the Tek screen: viewBox in 4013 points,
// polylines, the caption as text.
std::string svg_of(const Picture& picture);

}  // namespace igds
