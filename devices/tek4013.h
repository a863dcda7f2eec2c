// The Tektronix 4013 encoder (docs/devices.md, "Tektronix 4013"): graph-mode addresses shortened as
// the terminal allows, one GS per polyline, 7-bit bytes only, no CR or LF inside graph data.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "devices/device.h"

namespace igds {

inline constexpr char tek_gs = 0x1D, tek_us = 0x1F, tek_esc = 0x1B, tek_ff = 0x0C, tek_etx = 0x03;

// The whole address of (x, y): HiY LoY HiX LoX for 10 bits, HiY Extra LoY HiX LoX for 12.
std::string tek_address(int x, int y, int bits = 10);
// The point of a whole 10-bit address (four bytes, as tek_address writes it), or nullopt when
// the bytes are no address.
std::optional<DevicePoint> tek_address_point(std::string_view bytes);

// A Device that writes 4013 bytes. Coordinates are 0..1023 x 0..779 (10 bits) or four times
// that (12 bits); callers clip before (out-of-range values would corrupt the tag bits).
class TekEncoder : public Device {
 public:
  explicit TekEncoder(int bits = 10) : bits_(bits == 12 ? 12 : 10) {}

  void move(DevicePoint p) override;
  void draw(DevicePoint p) override;
  void text(DevicePoint p, std::string_view line) override;
  void polyline(std::span<const DevicePoint> points) override;
  // ESC FF, then the character size and the line style again (xterm keeps them across a page).
  void page() override;
  // The 4014's line styles for the dashes (ESC ` solid, a dotted, b dot-dashed, c short-dashed);
  // the 4013 has one pen and one weight.
  void style(const Style& style) override;
  // Characters in alpha mode where the alpha cursor is (printable 7-bit; others as '?').
  void append_text(std::string_view text);
  // Alpha mode with the cursor at `p`: where the dialogue goes on.
  void alpha_at(DevicePoint p);
  // Alpha mode where the beam is (US), unless already in alpha mode.
  void alpha();

  const std::string& bytes() const { return out_; }
  std::string take() {
    std::string bytes;
    bytes.swap(out_);
    return bytes;
  }

 private:
  enum class Mode { alpha, graph };
  void address(DevicePoint p);
  char* address(DevicePoint p, char* w);  // writes at w, returns the end

  int bits_;
  std::string out_;
  Mode mode_ = Mode::alpha;
  bool at_known_ = false;  // the beam is at at_ (graph mode only)
  DevicePoint at_;
  bool whole_ = true;  // the next address must be sent whole (after GS, text, a page)
  Dash dash_ = Dash::solid;
  int hi_y_ = -1, lo_y_ = -1, hi_x_ = -1;
};

}  // namespace igds
