// The report a Tektronix terminal sends in GIN mode (graphic input, ESC SUB: the cross-hair):
// the key pressed, then the cross-hair's position as four address bytes HiX LoX HiY LoY (five
// bits each, 0x20 | bits), then the terminator xterm's ginTerminator resource asks for: none,
// CR, or CR EOT. xterm sends a mouse button as its letter with the high bit set (l m r, 0xEC
// 0xED 0xF2) and the position in 10-bit units whatever the window's size (Tekproc.c, TekEnq).
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace igds {

struct GinReport {
  char key = 0;          // the key, 7-bit: a button's letter (l m r) or the key typed
  bool button = false;   // a mouse button (the key came with its high bit set)
  int x = 0, y = 0;      // the position in the host's addresses
  std::size_t used = 0;  // bytes of `bytes` the report took, its terminator included
};

// The report at the start of `bytes`, or nothing when they do not begin with one (fewer than
// five bytes, or an address byte outside 0x20..0x3F). `bits` is the width of the addresses the
// host draws with: 10 (the 4013) gives the position as sent, 12 (--tek 4014) the same place in
// 12-bit addresses (four times, the middle of the 4 x 4 cell). A CR, or a CR and an EOT, after
// the address is the terminator and counted in `used` (a LF for the CR too: a tty with ICRNL
// makes one of it); anything else is left for what follows.
std::optional<GinReport> decode_gin(std::string_view bytes, int bits = 10);

}  // namespace igds
