#include "devices/tek4013.h"

namespace igds {

namespace {

struct Address {
  char hi_y, extra, lo_y, hi_x, lo_x;
};

// docs/devices.md, "Tektronix 4013".
Address split(int x, int y, int bits) {
  if (bits == 12)
    return {static_cast<char>(0x20 | ((y >> 7) & 31)),
            static_cast<char>(0x60 | ((y & 3) << 2) | (x & 3)),
            static_cast<char>(0x60 | ((y >> 2) & 31)), static_cast<char>(0x20 | ((x >> 7) & 31)),
            static_cast<char>(0x40 | ((x >> 2) & 31))};
  return {static_cast<char>(0x20 | ((y >> 5) & 31)), 0, static_cast<char>(0x60 | (y & 31)),
          static_cast<char>(0x20 | ((x >> 5) & 31)), static_cast<char>(0x40 | (x & 31))};
}

}  // namespace

std::string tek_address(int x, int y, int bits) {
  Address a = split(x, y, bits);
  std::string s{a.hi_y};
  if (bits == 12) s += a.extra;
  s += a.lo_y;
  s += a.hi_x;
  s += a.lo_x;
  return s;
}

std::optional<DevicePoint> tek_address_point(std::string_view bytes) {
  if (bytes.size() != 4) return std::nullopt;
  // Each byte's tag (its two high bits) says which part of the address it is.
  const auto b = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  if ((b(0) & 0x60) != 0x20 || (b(1) & 0x60) != 0x60 || (b(2) & 0x60) != 0x20 ||
      (b(3) & 0x60) != 0x40 || ((b(0) | b(1) | b(2) | b(3)) & 0x80) != 0)
    return std::nullopt;
  return DevicePoint{(b(2) & 31) << 5 | (b(3) & 31), (b(0) & 31) << 5 | (b(1) & 31)};
}

char* TekEncoder::address(DevicePoint p, char* w) {
  Address a = split(p.x, p.y, bits_);
  // The terminal keeps the bytes it last received: send only what changed, LoY also before a
  // changed HiX (a high byte after LoY is HiX) and after Extra; LoX completes the address.
  bool extra = bits_ == 12;
  bool hi_x_changed = whole_ || a.hi_x != hi_x_;
  if (whole_ || a.hi_y != hi_y_) *w++ = a.hi_y;
  if (extra) *w++ = a.extra;
  if (whole_ || extra || hi_x_changed || a.lo_y != lo_y_) *w++ = a.lo_y;
  if (hi_x_changed) *w++ = a.hi_x;
  *w++ = a.lo_x;
  hi_y_ = a.hi_y, lo_y_ = a.lo_y, hi_x_ = a.hi_x;
  whole_ = false;
  at_ = p;
  at_known_ = true;
  return w;
}

void TekEncoder::address(DevicePoint p) {
  char bytes[5];
  char* end = address(p, bytes);
  out_.append(bytes, static_cast<std::size_t>(end - bytes));
}

void TekEncoder::move(DevicePoint p) {
  if (mode_ == Mode::graph && at_known_ && at_ == p) return;
  out_ += tek_gs;
  mode_ = Mode::graph;
  whole_ = true;
  address(p);
}

void TekEncoder::draw(DevicePoint p) {
  if (mode_ != Mode::graph || !at_known_) {
    // Nothing to draw from: the vector starts where the beam is not known.
    move(p);
    return;
  }
  if (at_ == p) return;
  address(p);
}

void TekEncoder::polyline(std::span<const DevicePoint> points) {
  if (points.empty()) return;
  move(points.front());
  // Written in place, with room for the longest address of every vector, then cut to size.
  std::size_t used = out_.size();
  out_.resize(used + 5 * (points.size() - 1));
  char* begin = out_.data() + used;
  char* w = begin;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (!(points[i] == at_)) w = address(points[i], w);
  out_.resize(used + static_cast<std::size_t>(w - begin));
}

void TekEncoder::text(DevicePoint p, std::string_view line) {
  alpha_at(p);
  for (char c : line) out_ += (c >= 0x20 && c < 0x7F) ? c : '?';
}

void TekEncoder::append_text(std::string_view text) {
  alpha();
  for (char c : text) out_ += (c >= 0x20 && c < 0x7F) ? c : '?';
}

void TekEncoder::alpha_at(DevicePoint p) {
  move(p);
  alpha();
}

void TekEncoder::alpha() {
  if (mode_ == Mode::alpha) return;
  out_ += tek_us;
  mode_ = Mode::alpha;
  at_known_ = false;
  whole_ = true;
}

void TekEncoder::style(const Style& style) {
  if (style.dash == dash_) return;
  dash_ = style.dash;
  char code = '`';
  switch (dash_) {
    case Dash::solid:
      code = '`';
      break;
    case Dash::dotted:
      code = 'a';
      break;
    case Dash::chain:
      code = 'b';
      break;
    case Dash::dashed:
      code = 'c';
      break;
  }
  out_ += {tek_esc, code};
}

void TekEncoder::page() {
  // ESC FF erases; ESC 8 the large (4013) characters; ESC ` solid lines.
  out_ += {tek_esc, tek_ff, tek_esc, '8', tek_esc, '`'};
  dash_ = Dash::solid;
  mode_ = Mode::alpha;
  at_known_ = false;
  whole_ = true;
}

}  // namespace igds
