#include "devices/menu_layout.h"

#include <algorithm>

namespace igds {

MenuLayout menu_layout(std::size_t items) {
  using namespace menu_screen;
  using namespace tek_screen;
  MenuLayout out;
  const int n = static_cast<int>(items);
  const int columns = std::max(1, (n + rows - 1) / rows);
  const int left = right - columns * box_width - (columns - 1) * gap;
  for (int k = 0; k < n; ++k) {
    const int column = k / rows, row = k % rows;
    const double x0 = right - (columns - column) * box_width - (columns - 1 - column) * gap;
    const double y1 = top - row * item_height;
    out.items.push_back({x0, y1 - (item_height - 2), x0 + box_width, y1});
  }
  out.menu = {double(left), double(bottom), double(right), double(top)};
  // The text area: eight rows at the bottom (tek mode's, layout.cpp), as wide as the menu lets.
  const TekLayout tek = dialogue_layout();
  const int text_right = left - 2 * gap;
  const int dialogue_columns = text_right / char_width;
  // The caption column just left of the menu, as wide as a caption line may be; the square of
  // the picture left of it, at most tek mode's.
  const int caption_x = text_right - static_cast<int>(caption_width) * char_width;
  const double side = std::min(tek.image.x1 - tek.image.x0, caption_x - 2.0 * gap - 1);
  out.screen = tek;
  out.screen.image = {0, tek.image.y1 - side, side, tek.image.y1};
  out.screen.caption_x = caption_x;
  out.screen.dialogue_columns = dialogue_columns;
  out.picture = out.screen.image;
  out.caption = {double(caption_x), out.screen.image.y0, double(text_right), double(top)};
  const int text_top = tek.dialogue_top + 16;  // the capitals of the first row
  out.text = {0, 0, double(dialogue_columns * char_width), double(text_top)};
  return out;
}

int item_at(const MenuLayout& layout, int x, int y) {
  for (std::size_t k = 0; k < layout.items.size(); ++k) {
    const Box& b = layout.items[k];
    if (x >= b.x0 && x <= b.x1 && y >= b.y0 && y <= b.y1) return static_cast<int>(k);
  }
  return -1;
}

Drawing2 menu_drawing(const MenuLayout& layout, std::span<const std::string> labels) {
  Drawing2 d;
  for (std::size_t k = 0; k < layout.items.size() && k < labels.size(); ++k) {
    const Box& b = layout.items[k];
    const Identity id{Role::menu, static_cast<int>(k)};
    const double corners[] = {b.x0, b.y0, b.x1, b.y0, b.x1, b.y1, b.x0, b.y1};
    d.add_polyline(Drawing2::View(corners, 4, 2), {}, id, true);
    // The label's cell (4 below its baseline to 16 above, 14 a character) clear of the edges.
    d.add_text({b.x0 + 6, b.y0 + 5}, labels[k], 1, {}, id);
  }
  return d;
}

}  // namespace igds
