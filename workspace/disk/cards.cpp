#include "workspace/disk/cards.h"

#include <cmath>

#include <fmt/format.h>

namespace igds::disk {

namespace {

constexpr int per_card = 8;  // (8F10.3)

void shape_card(std::string& out, const Array& a, std::size_t rank) {
  // An empty array keeps the card of its rank, all zeros, so that a reader's layout holds.
  for (std::size_t k = 0; k < rank; ++k)
    out += format_i(k < a.shape.size() && !a.empty() ? static_cast<long long>(a.shape[k]) : 0, 5);
  out += '\n';
}

void value_cards(std::string& out, const Array& a, std::size_t* overflow) {
  std::size_t n = 0;
  for (double v : a.ravel) {
    bool fits = true;
    out += format_f10_3(v, &fits);
    if (!fits) ++*overflow;
    if (++n % per_card == 0) out += '\n';
  }
  if (n % per_card != 0) out += '\n';
}

}  // namespace

std::string format_i(long long value, int width) {
  std::string s = fmt::format("{:>{}}", value, width);
  if (static_cast<int>(s.size()) > width) return std::string(static_cast<std::size_t>(width), '*');
  return s;
}

std::string format_f10_3(double value, bool* fits) {
  if (std::isnan(value)) return fmt::format("{:>10}", "NaN");
  if (std::isinf(value)) return fmt::format("{:>10}", value < 0 ? "-Infinity" : "Infinity");
  // fmt converts the exact binary value and rounds halves to even, like gfortran's default.
  std::string s = fmt::format("{:10.3f}", value);
  if (s.size() > 10) {
    *fits = false;
    return std::string(10, '*');
  }
  return s;
}

std::string char_cards(const Workspace& ws, std::size_t* overflow) {
  std::string out;
  *overflow = 0;
  for (int s : ws.status) out += format_i(s, 5);  // (10I5)
  out += '\n';
  for (int v : {ws.nocur, ws.nostr, ws.intcu, ws.intst}) out += format_i(v, 5);  // (4I5)
  out += '\n';
  shape_card(out, ws.inppn, 2);
  value_cards(out, ws.inppn, overflow);
  shape_card(out, ws.inptg, 2);
  value_cards(out, ws.inptg, overflow);
  shape_card(out, ws.intpn, 3);
  value_cards(out, ws.intpn, overflow);
  shape_card(out, ws.patches, 5);
  value_cards(out, ws.patches, overflow);
  return out;
}

}  // namespace igds::disk
