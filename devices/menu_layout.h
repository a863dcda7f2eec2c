// Where the 2250 workspace (manual section 5) puts things on the Tek screen, in 4013 points: the
// menu always shown in a column of boxes at the right, the picture and its caption at the top
// left, the text area (the dialogue) below the picture. Pure geometry: nothing here knows the
// commands (commands/menu.h makes the items) or the terminal.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "devices/layout.h"
#include "devices/render.h"
#include "workspace/drawing/drawing.h"

namespace igds {

namespace menu_screen {
inline constexpr int label_columns = 10;  // a label's characters ("D SURFACE", "ST SECOND")
inline constexpr int item_height = 23;    // one alpha line (22) and a point: 33 items a column
// A label's ten cells and room around them: xterm draws a character with its font's glyph from
// the start of its cell, and in a small window the glyph is wider than the scaled cell.
inline constexpr int box_width = label_columns * tek_screen::char_width + 24;
inline constexpr int gap = 4;       // between two columns of boxes
inline constexpr int right = 1020;  // the menu's right edge
inline constexpr int top = 766;     // the highest row xterm shows (docs/devices.md)
inline constexpr int bottom = 2;
inline constexpr int rows = (top - bottom) / item_height;  // items in one column
}  // namespace menu_screen

struct MenuLayout {
  std::vector<Box> items;  // one box per item, in the menu's order, down each column
  Box menu;                // the menu's area: every box is inside
  Box picture;             // the picture's square
  Box caption;             // the caption column
  Box text;                // the text area below the picture
  TekLayout screen;        // the same for the TekScreen (its dialogue stays left of the menu)
};

// The layout of a menu of `items` items: as many columns as they need, right to left, and the
// picture, caption and text area in what is left.
MenuLayout menu_layout(std::size_t items);

// The item whose box holds (x, y), or -1 (the picture, the text, between boxes).
int item_at(const MenuLayout& layout, int x, int y);

// The menu drawn: each box as a closed polyline and its label inside, both with the identity
// of menu item k (Role::menu), in 4013 points.
Drawing2 menu_drawing(const MenuLayout& layout, std::span<const std::string> labels);

}  // namespace igds
