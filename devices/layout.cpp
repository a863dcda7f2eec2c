#include "devices/layout.h"

namespace igds {

DevicePoint draw_tek_display(const Image& image, Device& device, int unit) {
  using namespace tek_screen;
  Picture pic = picture_of(image);
  const double lo = unit * image_margin, hi = unit * (image_side - 1 - image_margin);
  Placement at = fit(pic, {lo, lo, hi, hi}, unit * mark);
  Placed placed = place(pic, at, unit * mark, {0, 0, unit * (width - 1.0), unit * (height - 1.0)});
  for (const auto& path : placed.paths) draw_path(device, path);
  int y = text_top;
  for (const auto& line : pic.description) {
    device.text({unit * text_x, unit * y}, line);
    y -= line_height;
  }
  return below_description(pic.description.size(), unit);
}

DevicePoint below_description(std::size_t lines, int unit) {
  using namespace tek_screen;
  return {unit * text_x, unit * (text_top - static_cast<int>(lines) * line_height)};
}

}  // namespace igds
