#include "devices/layout.h"

namespace igds {

DevicePoint draw_tek_display(const Picture& picture, Device& device, int unit) {
  using namespace tek_screen;
  const double lo = unit * image_margin, hi = unit * (image_side - 1 - image_margin);
  const Placement at = fit(picture.drawing, {lo, lo, hi, hi}, unit * mark);
  render(picture.drawing, at, {0, 0, unit * (width - 1.0), unit * (height - 1.0)},
         Rendering{.point = double(unit)}, device);
  device.style({});
  int y = text_top;
  for (const auto& line : picture.caption) {
    device.text({unit * text_x, unit * y}, line);
    y -= line_height;
  }
  return below_description(picture.caption.size(), unit);
}

DevicePoint below_description(std::size_t lines, int unit) {
  using namespace tek_screen;
  return {unit * text_x, unit * (text_top - static_cast<int>(lines) * line_height)};
}

}  // namespace igds
