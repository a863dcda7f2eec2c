// The cursor an X server shows at the pointer, watched through the XFixes extension: how a test
// knows that xterm's Tek window is in GIN mode (its cursor is then a cross-hair) before it clicks.
#pragma once

#include <chrono>
#include <string>

namespace igds::test {

// False when the test support was built without libXfixes: nothing can be watched.
bool can_watch_cursor();

// Waits until the cursor at the pointer on `display` is a cross-hair other than the one whose
// serial is `previous` (xterm makes a new cross-hair each time GIN mode begins; 0: any one).
// Returns its serial, or 0 when none came within `limit`.
unsigned long await_crosshair(const std::string& display, unsigned long previous,
                              std::chrono::milliseconds limit);

}  // namespace igds::test
