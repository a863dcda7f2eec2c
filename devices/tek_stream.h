// The terminal modes (docs/devices.md, "Tektronix 4013"), and the 4013 streams of a picture alone
// on the screen (EXPORT TEK; the Tek screen of a session is devices/tek_screen.h).
#pragma once

#include <string>

#include "workspace/drawing/drawing.h"

namespace igds {

// tek: the Tek screen itself (dialogue in alpha mode); xterm: VT window with a Tek window
// beside it; none: images are not drawn on the terminal.
enum class TermMode { tek, xterm, none };

struct TekOptions {
  int bits = 10;  // 10 for the 4013 (1024 x 780), 12 for --tek 4014 (4096 x 3120)
};

// The bytes that draw `image` and its description on the left of the screen, ending in alpha
// mode: in tek mode the graph data itself, in xterm mode wrapped in ESC[?38h ... US ESC ETX,
// in none mode nothing.
std::string display_bytes(const Picture& picture, TermMode mode, TekOptions tek);

// ERASE: a page (ESC FF), with its character size and line style sent again; wrapped for xterm.
std::string erase_bytes(TermMode mode, TekOptions tek);

// The complete 4013 stream of one image (EXPORT TEK): a page, the image, the description.
std::string tek_stream(const Picture& picture, TekOptions tek);

}  // namespace igds
