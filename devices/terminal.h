// What a DISPLAY sends to the terminal, by terminal mode (spec tek4013.md).
#pragma once

#include <string>
#include <string_view>

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

// The dialogue on the Tek screen in tek mode: where its next line goes. Lines end in CR LF, a line
// too long for the screen is broken at its right edge (as the terminal would, but counted), and a
// line that would fall below the bottom of the screen goes back to the top left instead. (A 4013
// would go on in the right half, over the description; tek2plot, unlike xterm, keeps writing
// there after a page.) DISPLAY, ERASE and the start of a session move the alpha cursor: say so.
class TekDialogue {
 public:
  explicit TekDialogue(TekOptions tek) : tek_(tek) {}
  // The alpha cursor to the top left, without erasing (a storage tube keeps what it shows): where
  // the dialogue starts, and goes on after a page.
  std::string home();
  // `text` with each line end made CR LF, or a move back to the top left at the bottom.
  std::string text(std::string_view text);
  // After display_bytes: the dialogue goes on at the line below the image's description.
  void displayed(const Picture& picture);

 private:
  void new_line(std::string& out);

  TekOptions tek_;
  int baseline_ = 0;  // of the line being written, in 4013 points
  int x_ = 0;         // where that line started, in 4013 points
  int column_ = 0;    // characters written on it
};

// The complete 4013 stream of one image (EXPORT TEK): a page, the image, the description.
std::string tek_stream(const Picture& picture, TekOptions tek);

}  // namespace igds
