// The layout of a DISPLAY on the Tek screen (spec tek4013.md, Layout of a DISPLAY), shared by
// the 4013 stream and the SVG so that both carry the same coordinates.
#pragma once

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

// Where the dialogue goes on after a DISPLAY whose description has `lines` lines: the start of
// the line below it, at x = 780 (in device units, `unit` times the 4013's).
DevicePoint below_description(std::size_t lines, int unit);

// Draws `picture` in the left square of the screen and its caption, one item per line, at
// x = 780 on `device`, whose units are `unit` times the 4013's (1 for 10-bit, 4 for 12-bit).
// Returns where the dialogue goes on: the start of the line below the caption.
DevicePoint draw_tek_display(const Picture& picture, Device& device, int unit);

// The longest caption line: the 17 columns of the Tek screen right of the image.
inline constexpr std::size_t caption_width = tek_screen::text_columns;

}  // namespace igds
