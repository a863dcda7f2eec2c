// A decoder of 4013 streams that says what a terminal would show: the vectors and the
// characters of each page, in 4013 points; and the faults of a page that igds must never make
// (a character over another or over a vector, something off the screen).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace igds::test {

// What a 4013 stream draws, in 4013 points (10-bit addresses; 12-bit ones are divided by 4).
struct TekPoint {
  double x = 0, y = 0;
};
struct TekSegment {
  TekPoint a, b;  // a == b: a point (FS point plot)
};
struct TekText {
  TekPoint at;  // the baseline-left of the first character
  std::string text;
};
struct TekPage {
  std::vector<TekSegment> segments;
  std::vector<TekText> texts;
};
struct TekDrawing {
  std::vector<TekPage> pages;       // split at every ESC FF, as tek2plot --page-number counts
  std::vector<std::string> errors;  // bytes a 4013 would not accept where they are
};

// Decodes a 4013 stream: GS/FS/US modes, shortened addresses (10 or 12 bits), ESC FF pages,
// alpha text with CR/LF (4013 cell: 14 x 22 points, home at the top left).
TekDrawing decode_tek(std::string_view stream);

// The shortest distance from `p` to the segment.
double distance(TekPoint p, const TekSegment& s);

// What is wrong with a page, one line each: characters drawn over characters or over vectors,
// anything off the screen (beyond x 1023, or above the 767th row that xterm shows). A character
// occupies its alpha cell, 14 points wide, from 4 below its baseline to 16 above.
std::vector<std::string> screen_faults(const TekPage& page);

}  // namespace igds::test
