#include "devices/gin.h"

#include <cstdlib>

namespace igds {

namespace {

bool address_byte(char c) {
  const auto b = static_cast<unsigned char>(c);
  return b >= 0x20 && b <= 0x3F;
}

bool carriage_return(char c) {
  return c == '\r' || c == '\n';
}

enum class Fit { whole, short_of, none };

// Whether the bytes begin with a report ending in `terminator` bytes (CR, then EOT).
Fit report_fits(std::string_view bytes, std::size_t terminator) {
  for (std::size_t i = 1; i < 5 + terminator; ++i) {
    if (i >= bytes.size()) return Fit::short_of;
    const char c = bytes[i];
    if (!(i < 5 ? address_byte(c) : i == 5 ? carriage_return(c) : c == '\x04')) return Fit::none;
  }
  return Fit::whole;
}

constexpr std::size_t npos = std::string::npos;

// The length of the escape sequence the bytes begin with, as xterm sends keys (ESC or 8-bit CSI
// and SS3): 0 when they begin with none, npos while it is not whole.
std::size_t sequence_length(std::string_view bytes) {
  const auto at = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  std::size_t from = 1;
  if (at(0) == 0x1B) {
    if (bytes.size() < 2) return npos;
    if (bytes[1] == 'O') return bytes.size() < 3 ? npos : 3;
    if (bytes[1] != '[') return 2;
    from = 2;
  } else if (at(0) == 0x8F) {
    return bytes.size() < 2 ? npos : 2;
  } else if (at(0) != 0x9B) {
    return 0;
  }
  for (std::size_t i = from; i < bytes.size(); ++i) {
    if (at(i) >= 0x40 && at(i) <= 0x7E) return i + 1;  // the final byte
    if (at(i) < 0x20 || at(i) > 0x3F) return i;        // cut short: the next byte is not its
  }
  return npos;
}

}  // namespace

std::optional<GinReport> decode_gin(std::string_view bytes, int bits) {
  if (bytes.size() < 5) return std::nullopt;
  int five[4];
  for (int i = 0; i < 4; ++i) {
    const char b = bytes[static_cast<std::size_t>(i) + 1];
    if (!address_byte(b)) return std::nullopt;  // not an address byte of a report
    five[i] = b & 0x1F;
  }
  GinReport report;
  const auto key = static_cast<unsigned char>(bytes[0]);
  report.key = static_cast<char>(key & 0x7F);
  report.button = (key & 0x80) != 0;
  report.x = (five[0] << 5) | five[1];
  report.y = (five[2] << 5) | five[3];
  if (bits == 12) {
    report.x = report.x * 4 + 2;
    report.y = report.y * 4 + 2;
  }
  report.used = 5;
  if (bytes.size() > 5 && carriage_return(bytes[5])) {
    report.used = 6;
    if (bytes.size() > 6 && bytes[6] == '\x04') report.used = 7;
  }
  return report;
}

std::string gin_address(int x, int y) {
  return {static_cast<char>(0x20 | ((x >> 5) & 0x1F)), static_cast<char>(0x20 | (x & 0x1F)),
          static_cast<char>(0x20 | ((y >> 5) & 0x1F)), static_cast<char>(0x20 | (y & 0x1F))};
}

GinReader::GinReader(int mark_x, int mark_y, int bits)
    : mark_(gin_address(mark_x, mark_y)), bits_(bits) {}

void GinReader::feed(std::string_view bytes) {
  bytes_ += bytes;
  scan();
}

bool GinReader::unsettled() const {
  return mark_end_ != npos && (terminator_ < 0 || (!done() && searched_ < bytes_.size()));
}

void GinReader::settle() {
  if (mark_end_ == npos) return;
  if (terminator_ < 0) {
    // Whatever terminator bytes have come are all there is.
    terminator_ = mark_end_ < bytes_.size() ? 1 : 0;
    searched_ = mark_end_ + static_cast<std::size_t>(terminator_);
    scan();
  } else if (!done() && searched_ < bytes_.size()) {
    typed_at_ = searched_;  // a report begun and never ended: keys
  }
}

std::string_view GinReader::ahead() const {
  return std::string_view(bytes_).substr(0, mark_at_ == npos ? 0 : mark_at_);
}

std::string_view GinReader::rest() const {
  if (report_) return std::string_view(bytes_).substr(report_end_);
  return typed() ? std::string_view(bytes_).substr(typed_at_) : std::string_view{};
}

std::string_view GinReader::after_mark() const {
  if (!marked()) return {};
  return std::string_view(bytes_).substr(mark_end_ + static_cast<std::size_t>(terminator_));
}

void GinReader::scan() {
  if (mark_end_ == npos) {
    // The mark: a status byte (printable), then exactly the address igds put the cursor at.
    for (std::size_t at = 0; at + 5 <= bytes_.size(); ++at) {
      const auto status = static_cast<unsigned char>(bytes_[at]);
      if (status >= 0x20 && status < 0x7F && bytes_.compare(at + 1, 4, mark_) == 0) {
        mark_at_ = at;
        mark_end_ = at + 5;
        break;
      }
    }
    if (mark_end_ == npos) return;
  }
  if (terminator_ < 0) {
    // The terminator: CR (or LF), then perhaps EOT; decided once the byte after each has come.
    const std::size_t n = bytes_.size();
    if (n == mark_end_) return;
    if (!carriage_return(bytes_[mark_end_])) {
      terminator_ = 0;
    } else {
      if (n == mark_end_ + 1) return;
      terminator_ = bytes_[mark_end_ + 1] == '\x04' ? 2 : 1;
    }
    searched_ = mark_end_ + static_cast<std::size_t>(terminator_);
  }
  if (done()) return;
  const auto t = static_cast<std::size_t>(terminator_);
  while (searched_ < bytes_.size()) {
    const std::string_view from = std::string_view(bytes_).substr(searched_);
    const Fit fit = report_fits(from, t);
    if (fit == Fit::whole) {
      report_ = decode_gin(from.substr(0, 5), bits_);
      report_->used = 5 + t;
      report_end_ = searched_ + 5 + t;
      return;
    }
    if (fit == Fit::short_of) return;
    const std::size_t sequence = sequence_length(from);
    if (sequence == npos) return;
    if (sequence == 0) {
      typed_at_ = searched_;  // no report can begin here: keys sent as they are
      return;
    }
    searched_ += sequence;  // a key that sends no report (an arrow's sequence)
  }
}

std::string without_clicks(std::string_view keys, int terminator) {
  std::string out;
  for (std::size_t i = 0; i < keys.size();) {
    if (static_cast<unsigned char>(keys[i]) >= 0xC0 &&
        report_fits(keys.substr(i), static_cast<std::size_t>(terminator)) == Fit::whole) {
      i += 5 + static_cast<std::size_t>(terminator);
      continue;
    }
    out += keys[i++];
  }
  return out;
}

bool second_click(const GinReport& first, std::chrono::steady_clock::time_point first_at,
                  const GinReport& next, std::chrono::steady_clock::time_point next_at) {
  return first.button && next.button && first.key == next.key && std::abs(first.x - next.x) <= 8 &&
         std::abs(first.y - next.y) <= 8 && next_at - first_at < double_click;
}

}  // namespace igds
