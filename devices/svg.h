// EXPORT SVG: the Tek screen of a DISPLAY as a standalone SVG document.
#pragma once

#include <string>
#include <string_view>

#include "devices/device.h"

namespace igds {

// A Device that writes SVG elements in the 1024 x 780 space of the 4013, y flipped: the 4013
// point (x, y) is the SVG point (x, 779 - y). Polylines become <polyline>, text <text>.
class SvgWriter : public Device {
 public:
  void move(DevicePoint p) override;
  void draw(DevicePoint p) override;
  void text(DevicePoint p, std::string_view line) override;
  void page() override;
  // The whole document.
  std::string document();

 private:
  void close_polyline();

  std::string body_;
  std::string points_;  // the polyline being drawn
  DevicePoint at_;
  bool at_known_ = false;
  bool drawing_ = false;
};

}  // namespace igds
