#include "devices/layout.h"

namespace igds {

TekLayout full_layout() {
  using namespace tek_screen;
  return {.image = {0, 0, image_side - 1.0, image_side - 1.0},
          .caption_x = text_x,
          .caption_top = text_top,
          .caption_rows = text_top / line_height + 1};
}

TekLayout dialogue_layout() {
  using namespace tek_screen;
  // Eight lines of dialogue, baselines 160 down to 6; their capitals reach 176. The square sits
  // above them, up to the 767th row that xterm still shows.
  constexpr int rows = 8, bottom = 6, top = bottom + (rows - 1) * line_height;
  constexpr double low = 184, side = image_side - low;
  return {.image = {0, low, side - 1, image_side - 1.0},
          .caption_x = 600,
          .caption_top = text_top,
          .caption_rows = (text_top - static_cast<int>(low) - 6) / line_height + 1,
          .dialogue_top = top,
          .dialogue_rows = rows};
}

bool draw_picture(const Picture& picture, Device& device, int unit, const TekLayout& layout) {
  using namespace tek_screen;
  const Box& sq = layout.image;
  const Box box{unit * (sq.x0 + image_margin), unit * (sq.y0 + image_margin),
                unit * (sq.x1 - image_margin), unit * (sq.y1 - image_margin)};
  const Placement at = fit(picture.drawing, box, unit * mark);
  // A text never runs into the caption (nor, on a 4013, past the screen's edge, where it would
  // go on at the left over the picture).
  const Rendering rendering{.point = double(unit),
                            .char_width = double(unit * char_width),
                            .text_right = double(unit * (layout.caption_x - char_width / 2))};
  bool cut = false;
  render(picture.drawing, at, {0, 0, unit * (width - 1.0), unit * (height - 1.0)}, rendering,
         device, &cut);
  device.style({});
  return cut;
}

DevicePoint draw_tek_display(const Picture& picture, Device& device, int unit) {
  using namespace tek_screen;
  const bool cut = draw_picture(picture, device, unit, full_layout());
  int y = text_top;
  for (const auto& line : picture.caption) {
    device.text({unit * text_x, unit * y}, line);
    y -= line_height;
  }
  if (cut) device.text({unit * text_x, unit * y}, texts_cut_line);
  return below_description(picture.caption.size() + (cut ? 1 : 0), unit);
}

DevicePoint below_description(std::size_t lines, int unit) {
  using namespace tek_screen;
  return {unit * text_x, unit * (text_top - static_cast<int>(lines) * line_height)};
}

}  // namespace igds
