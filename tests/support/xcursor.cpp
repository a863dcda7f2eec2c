// igds_xcursor: the shape of the mouse pointer on the X display, as "WIDTH HEIGHT XHOT YHOT" (the
// XFIXES extension's cursor image): the end-to-end tests wait for xterm's cross-hair, a cursor
// with its hot spot in the middle, before they click, instead of sleeping.
#include <X11/Xlib.h>
#include <X11/extensions/Xfixes.h>

#include <cstdio>

int main() {
  Display* display = XOpenDisplay(nullptr);
  if (!display) return 2;
  int event = 0, error = 0;
  if (!XFixesQueryExtension(display, &event, &error)) return 3;
  XFixesCursorImage* cursor = XFixesGetCursorImage(display);
  if (!cursor) return 4;
  std::printf("%d %d %d %d\n", cursor->width, cursor->height, cursor->xhot, cursor->yhot);
  XFree(cursor);
  XCloseDisplay(display);
  return 0;
}
