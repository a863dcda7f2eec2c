// The layout of a DISPLAY on the Tek screen (docs/devices.md, "Tektronix 4013"), shared by
// the 4013 stream and the SVG so that both carry the same coordinates.
#pragma once

#include <string_view>

#include "devices/device.h"
#include "devices/render.h"
#include "workspace/drawing/drawing.h"

namespace igds {

// The 4013 screen in 4013 points (10-bit addresses); a 12-bit device multiplies them by 4.
namespace tek_screen {
inline constexpr int width = 1024, height = 780;
inline constexpr int image_side = 768;   // the image square 0..767: xterm hides the rows above
inline constexpr int image_margin = 16;  // on every side of the square
inline constexpr int mark = 3;           // half side of an input point's square
inline constexpr int text_x = 780;       // the description's column
inline constexpr int text_top = 734;     // baseline of its first line
inline constexpr int line_height = 22;   // 4013 alpha: 35 lines of 22 points
inline constexpr int char_width = 14;    // 4013 alpha: 74 characters of 14 points
inline constexpr int text_columns = (width - text_x) / char_width;  // 17: never past x = 1023
}  // namespace tek_screen

// Where things go on the Tek screen, in 4013 points.
struct TekLayout {
  Box image;             // the picture's square
  int caption_x = 0;     // the caption column
  int caption_top = 0;   // the baseline of its first line
  int caption_rows = 0;  // lines that fit in it
  int dialogue_top = 0;  // the baseline of the first line of dialogue below the picture
  int dialogue_rows = 0;
  int dialogue_columns = 0;  // characters of a dialogue row; 0: the whole width (text_columns)
};

// The picture alone on the screen (EXPORT TEK, EXPORT SVG, the Tek window of --term xterm): the
// square 0..767, the caption at x = 780 from the top.
TekLayout full_layout();

// Tek mode, where the dialogue shares the screen: the picture in the square 0..583 at the top
// left, the caption at x = 600, eight full lines of dialogue (73 characters) below the picture.
TekLayout dialogue_layout();

// The layout a picked address is read in (docs/devices.md, "The cross-hair"): `screen`, the
// screen as the terminal mode draws it (a cross-hair pick, or X Y typed by a person who sees the
// picture); `page`, full_layout's, the page of EXPORT TEK and of --term none (a command file's
// X Y, so that one file names the same place under every terminal mode).
enum class PickLayout { screen, page };

// A position picked, in 4013 addresses (0..1023, 0..779), and the layout it is in.
struct PickedAddress {
  DevicePoint at;
  PickLayout layout = PickLayout::screen;
};

// A page without a picture: the dialogue over the whole screen, 34 lines of 73 characters.
inline constexpr int text_rows = tek_screen::text_top / tek_screen::line_height + 1;
inline constexpr int text_columns = (tek_screen::width - 1) / tek_screen::char_width;

// Draws the picture (not its caption) in the layout's square, its texts cut at the caption's
// column. Returns true when a text was cut: the caption then says so (texts_cut_line).
bool draw_picture(const Picture& picture, Device& device, int unit, const TekLayout& layout);

// The caption line that says a text of the picture was cut at the caption's column (or at the
// paper's caption strip, on HP-GL).
inline constexpr std::string_view texts_cut_line = "TEXTS CUT";

// Where the dialogue goes on after a DISPLAY whose description has `lines` lines: the start of
// the line below it, at x = 780 (in device units, `unit` times the 4013's).
DevicePoint below_description(std::size_t lines, int unit);

// Draws `picture` in the left square of the screen and its caption, one item per line, at
// x = 780 on `device`, whose units are `unit` times the 4013's (1 for 10-bit, 4 for 12-bit);
// TEXTS CUT after the caption when a text was. Returns where the dialogue goes on: the start of
// the line below the caption.
DevicePoint draw_tek_display(const Picture& picture, Device& device, int unit);

// The longest caption line: the 17 columns of the Tek screen right of the image.
inline constexpr std::size_t caption_width = tek_screen::text_columns;

}  // namespace igds
