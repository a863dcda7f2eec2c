// The characters beyond ASCII that igds may show on a Tektronix screen (the APL symbols, a few
// signs of its texts), as strokes: the 4013 had an APL character set, xterm's Tek window shows
// only ASCII (docs/devices.md, "The Tek screen").
#pragma once

#include <span>

#include "devices/device.h"

namespace igds {

// The 4013's alpha cell, in its points: 74 characters of 14 x 35 lines of 22. Glyphs are drawn
// about x 1..11, on a baseline at y = 0, capitals 14 high, descenders to -5 (within x 0..13,
// y -6..21).
inline constexpr int tek_cell_width = 14, tek_cell_height = 22;

// A point of a glyph, in cell units from the baseline-left corner of its cell.
struct GlyphPoint {
  double x = 0, y = 0;
};
// One polyline of a glyph.
using GlyphStroke = std::span<const GlyphPoint>;

// The strokes of `c`; empty when it has no glyph (ASCII, and what igds never shows).
std::span<const GlyphStroke> tek_glyph(char32_t c);
bool has_tek_glyph(char32_t c);

// Every character with a glyph, in increasing order.
std::span<const char32_t> tek_glyph_characters();

// Draws `c` with its cell's baseline-left corner at `origin`, `scale` device units a cell unit
// (1 for 10-bit addresses, 4 for 12-bit ones), each point rounded to the nearest unit. False,
// drawing nothing, when `c` has no glyph.
bool draw_tek_glyph(Device& device, DevicePoint origin, char32_t c, int scale = 1);

}  // namespace igds
