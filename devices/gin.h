// The report a Tektronix terminal sends in GIN mode (graphic input, ESC SUB: the cross-hair):
// the key pressed, then the cross-hair's position as four address bytes HiX LoX HiY LoY (five
// bits each, 0x20 | bits), then the terminator xterm's ginTerminator resource asks for: none,
// CR, or CR EOT. xterm sends a mouse button as its letter with the high bit set (l m r, 0xEC
// 0xED 0xF2), a key as its first byte, and the position in 10-bit units whatever the window's
// size; it leaves GIN mode with the report, and on any control character it is sent
// (docs/devices.md, "The cross-hair").
#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
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

// The four address bytes of a position in 4013 points, as a report or ESC ENQ's answer has them.
std::string gin_address(int x, int y);

// What the terminal sends while igds waits at a cross-hair question, read in step whatever else
// arrives and however it is cut into reads. Just before GIN mode igds puts the alpha cursor at a
// place of its choice and asks for the terminal's status (ESC ENQ): the answer, a status byte
// and that place's address, is the mark. Bytes before it are keys typed before the cross-hair
// was up. After it, in GIN mode, xterm sends the report, or first the keys it sends as they are
// with the cross-hair left up: an escape sequence (an arrow, a function key), dropped, or a plain
// key (the numeric keypad, or a key pressed between the terminal's reading of ESC ENQ and of ESC
// SUB). Those are typed: the report is looked for at the first byte that is no escape sequence
// only, and bytes there that cannot be one, or that stop short of one, are keys, never read as
// addresses. What follows the report was typed after it. The mark also tells which terminator
// the terminal ends its answers with.
class GinReader {
 public:
  // `mark_x`, `mark_y`: where the alpha cursor was put, in 4013 points.
  GinReader(int mark_x, int mark_y, int bits);

  // Bytes as they arrive.
  void feed(std::string_view bytes);
  // Nothing more came for a while (a report comes whole, in one write): where the mark's
  // terminator might still follow, it has none, or only the CR of CR EOT; else bytes after the
  // mark that began a report without ending one are keys.
  void settle();

  bool marked() const { return mark_end_ != npos && terminator_ >= 0; }
  // The mark has been read, up to where its terminator or a report begun may still follow: wait
  // a moment (then settle()) rather than for ever.
  bool unsettled() const;
  // A report, or keys after the mark (typed()).
  bool done() const { return report_.has_value() || typed_at_ != npos; }
  // Keys came after the mark where the report was looked for: the terminal may still be in GIN
  // mode.
  bool typed() const { return typed_at_ != npos; }

  // The bytes before the mark (known as soon as the mark is found).
  std::string_view ahead() const;
  const std::optional<GinReport>& report() const { return report_; }
  // The bytes after the report, or from the first key typed after the mark.
  std::string_view rest() const;
  // The bytes after the mark and its terminator, report or not.
  std::string_view after_mark() const;
  // The terminator's length, 0 to 2 (-1 until it is known).
  int terminator() const { return terminator_; }

 private:
  static constexpr std::size_t npos = std::string::npos;
  void scan();

  std::string mark_;  // the mark's address bytes
  int bits_;
  std::string bytes_;
  std::size_t mark_at_ = npos, mark_end_ = npos;  // the mark's status byte; just after its address
  int terminator_ = -1;
  std::size_t searched_ = 0;  // where the report is looked for
  std::optional<GinReport> report_;
  std::size_t report_end_ = 0;
  std::size_t typed_at_ = npos;  // the first key after the mark that is no report
};

// `keys` (typed where a report may have come among them) without a mouse button's report: its
// letter with the high bit set (a UTF-8 lead byte, which never has an address byte after it in
// text), four address bytes and `terminator` bytes of CR or EOT.
std::string without_clicks(std::string_view keys, int terminator);

// Two clicks of one button, at one place, less than `interval` apart: a double click, which
// chooses once (xterm reports each click that finds GIN mode on).
inline constexpr std::chrono::milliseconds double_click{400};
bool second_click(const GinReport& first, std::chrono::steady_clock::time_point first_at,
                  const GinReport& next, std::chrono::steady_clock::time_point next_at);

}  // namespace igds
