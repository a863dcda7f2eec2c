#include "devices/gin.h"

namespace igds {

std::optional<GinReport> decode_gin(std::string_view bytes, int bits) {
  if (bytes.size() < 5) return std::nullopt;
  int five[4];
  for (int i = 0; i < 4; ++i) {
    const auto b = static_cast<unsigned char>(bytes[static_cast<std::size_t>(i) + 1]);
    if (b < 0x20 || b > 0x3F) return std::nullopt;  // not an address byte of a report
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
  if (bytes.size() > 5 && (bytes[5] == '\r' || bytes[5] == '\n')) {
    report.used = 6;
    if (bytes.size() > 6 && bytes[6] == '\x04') report.used = 7;
  }
  return report;
}

}  // namespace igds
