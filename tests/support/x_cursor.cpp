#include "tests/support/x_cursor.h"

#ifdef IGDS_HAVE_XFIXES
#include <X11/Xlib.h>
#include <X11/extensions/Xfixes.h>
#include <poll.h>
#endif

namespace igds::test {

#ifdef IGDS_HAVE_XFIXES

namespace {

// A cross-hair: the hot spot inside the image, and its row and column opaque from edge to edge
// (xterm's arrow has its hot spot in a corner, the root window's X a gap in the middle).
bool crosshair(const XFixesCursorImage& c) {
  if (c.xhot <= 0 || c.yhot <= 0 || c.xhot + 1 >= c.width || c.yhot + 1 >= c.height) return false;
  auto opaque = [&](int x, int y) { return (c.pixels[y * c.width + x] >> 24) != 0; };
  for (int x = 0; x < c.width; ++x)
    if (!opaque(x, c.yhot)) return false;
  for (int y = 0; y < c.height; ++y)
    if (!opaque(c.xhot, y)) return false;
  return true;
}

}  // namespace

bool can_watch_cursor() {
  return true;
}

unsigned long await_crosshair(const std::string& display, unsigned long previous,
                              std::chrono::milliseconds limit) {
  Display* x = XOpenDisplay(display.c_str());
  if (!x) return 0;
  int event_base = 0, error_base = 0;
  unsigned long found = 0;
  if (XFixesQueryExtension(x, &event_base, &error_base)) {
    // Told of every change from here on, then the cursor shown now: no change is missed.
    XFixesSelectCursorInput(x, DefaultRootWindow(x), XFixesDisplayCursorNotifyMask);
    const auto deadline = std::chrono::steady_clock::now() + limit;
    for (;;) {
      if (XFixesCursorImage* image = XFixesGetCursorImage(x)) {
        if (image->cursor_serial != previous && crosshair(*image)) found = image->cursor_serial;
        XFree(image);
      }
      if (found) break;
      // The next change of cursor, or the end of the wait.
      bool changed = false;
      while (!changed) {
        while (!changed && XPending(x)) {
          XEvent event;
          XNextEvent(x, &event);
          changed = event.type == event_base + XFixesCursorNotify;
        }
        if (changed) break;
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) break;
        pollfd fd{ConnectionNumber(x), POLLIN, 0};
        poll(&fd, 1, static_cast<int>(left.count()));
      }
      if (!changed) break;
    }
  }
  XCloseDisplay(x);
  return found;
}

#else

bool can_watch_cursor() {
  return false;
}

unsigned long await_crosshair(const std::string&, unsigned long, std::chrono::milliseconds) {
  return 0;
}

#endif

}  // namespace igds::test
