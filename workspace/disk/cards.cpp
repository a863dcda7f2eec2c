#include "workspace/disk/cards.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace igds::disk {

namespace {

constexpr std::size_t per_card = 8;  // (8F10.3)
constexpr std::size_t i5 = 5, f10 = 10;

// Room for `bytes` in `out`, asked for as transparent huge pages where the system allows
// (Linux): on a virtual machine, faulting in 4 KB pages one by one costs more than writing the
// cards. Advice only: a refusal leaves the ordinary pages.
void reserve_large(std::string& out, std::size_t bytes) {
  out.reserve(bytes);
#ifdef __linux__
  const std::uintptr_t page = 4096;
  const auto from = (reinterpret_cast<std::uintptr_t>(out.data()) + page - 1) & ~(page - 1);
  const auto to = (reinterpret_cast<std::uintptr_t>(out.data()) + out.capacity()) & ~(page - 1);
  if (to > from && to - from >= (std::uintptr_t(1) << 22))
    madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
#endif
}

// Writes the decimal digits of v ending just before `end`; returns where they start.
char* digits_before(char* end, std::uint64_t v) {
  do {
    *--end = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v != 0);
  return end;
}

// Right-aligns text (of at most width characters) in `width` columns at out.
void right_aligned(char* out, std::size_t width, const char* text) {
  std::size_t n = std::strlen(text);
  std::memset(out, ' ', width - n);
  std::memcpy(out + width - n, text, n);
}

char* shape_card(char* w, const Array& a, std::size_t rank) {
  // An empty array keeps the card of its rank, all zeros, so that a reader's layout holds.
  for (std::size_t k = 0; k < rank; ++k, w += i5)
    put_i(w, k < a.shape.size() && !a.empty() ? static_cast<long long>(a.shape[k]) : 0, i5);
  *w++ = '\n';
  return w;
}

// The (8F10.3) cards of values[first, last): `first` starts a card; a last card of fewer than
// eight values ends the array.
char* value_cards(char* w, std::span<const double> values, std::size_t first, std::size_t last,
                  std::size_t* overflow) {
  for (std::size_t k = first; k < last; ++k) {
    if (!put_f10_3(w, values[k])) ++*overflow;
    w += f10;
    if ((k + 1) % per_card == 0) *w++ = '\n';
  }
  if (last == values.size() && last % per_card != 0) *w++ = '\n';
  return w;
}

std::size_t value_cards_size(const Array& a) {
  return a.size() * f10 + (a.size() + per_card - 1) / per_card;
}

}  // namespace

bool put_i(char* out, long long value, int width) {
  const auto w = static_cast<std::size_t>(width);
  const bool negative = value < 0;
  // The magnitude as unsigned, so that the most negative value has one too.
  const std::uint64_t magnitude =
      negative ? 0 - static_cast<std::uint64_t>(value) : static_cast<std::uint64_t>(value);
  char text[24];
  char* end = text + sizeof text;
  char* first = digits_before(end, magnitude);
  if (negative) *--first = '-';
  const auto n = static_cast<std::size_t>(end - first);
  if (n > w) {
    std::memset(out, '*', w);
    return false;
  }
  std::memset(out, ' ', w - n);
  std::memcpy(out + w - n, first, n);
  return true;
}

bool put_f10_3(char* out, double value) {
  if (std::isnan(value)) {
    right_aligned(out, f10, "NaN");
    return true;
  }
  if (std::isinf(value)) {
    right_aligned(out, f10, value < 0 ? "-Infinity" : "Infinity");
    return true;
  }
  // The value is m * 2^e exactly (IEEE 754 binary64): m the 53-bit significand.
  const auto bits = std::bit_cast<std::uint64_t>(value);
  const bool negative = bits >> 63;
  const int biased = static_cast<int>((bits >> 52) & 0x7FF);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  const std::uint64_t m = biased == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
  const int e = biased == 0 ? -1074 : biased - 1075;
  // Ten columns hold 999999.999 and -99999.999: the thousandths that no longer fit.
  const std::uint64_t limit = negative ? 100000000 : 1000000000;
  // |value| * 1000 rounded to an integer, exact halves to even: m * 1000 < 2^63 fits, and the
  // 2^e is a shift. Any e >= 0 means |value| >= 2^52, far past the limit.
  std::uint64_t q = limit;
  if (e < 0) {
    const std::uint64_t x = m * 1000;
    const int s = -e;
    if (s >= 64) {
      q = 0;  // x < 2^63 <= half of 2^s: less than half a thousandth
    } else {
      q = x >> s;
      const std::uint64_t rest = x & ((std::uint64_t{1} << s) - 1),
                          half = std::uint64_t{1} << (s - 1);
      if (rest > half || (rest == half && (q & 1))) ++q;
    }
  }
  if (q >= limit) {
    std::memset(out, '*', f10);
    return false;
  }
  char* w = out + f10;
  const std::uint64_t thousandths = q % 1000;
  *--w = static_cast<char>('0' + thousandths % 10);
  *--w = static_cast<char>('0' + thousandths / 10 % 10);
  *--w = static_cast<char>('0' + thousandths / 100);
  *--w = '.';
  w = digits_before(w, q / 1000);
  if (negative) *--w = '-';
  std::memset(out, ' ', static_cast<std::size_t>(w - out));
  return true;
}

std::string format_i(long long value, int width) {
  std::string s(static_cast<std::size_t>(width), ' ');
  put_i(s.data(), value, width);
  return s;
}

std::string format_f10_3(double value, bool* fits) {
  std::string s(f10, ' ');
  if (!put_f10_3(s.data(), value)) *fits = false;
  return s;
}

CardMaker::CardMaker(const Workspace& ws)
    : ws_(ws), arrays_{{{&ws.inppn, 2}, {&ws.inptg, 2}, {&ws.intpn, 3}, {&ws.patches, 5}}} {}

std::size_t CardMaker::size() const {
  // (10I5), (4I5), then a shape card and the value cards of each array.
  std::size_t size = ws_.status.size() * i5 + 1 + 4 * i5 + 1;
  for (const auto& [a, rank] : arrays_) size += rank * i5 + 1 + value_cards_size(*a);
  return size;
}

std::size_t CardMaker::fill(char* out, std::size_t room) {
  char* w = out;
  // Whole cards only, while the longest one still fits.
  while (static_cast<std::size_t>(out + room - w) >= longest_card) {
    if (!headed_) {
      for (int s : ws_.status) put_i(w, s, i5), w += i5;
      *w++ = '\n';
      for (int v : {ws_.nocur, ws_.nostr, ws_.intcu, ws_.intst}) put_i(w, v, i5), w += i5;
      *w++ = '\n';
      headed_ = true;
      continue;
    }
    if (array_ == arrays_.size()) break;
    const auto& [a, rank] = arrays_[array_];
    if (!shaped_) {
      w = shape_card(w, *a, rank);
      shaped_ = true;
      next_ = 0;
      continue;
    }
    const std::size_t cards = static_cast<std::size_t>(out + room - w) / longest_card;
    const std::size_t last = std::min(a->size(), next_ + cards * per_card);
    w = value_cards(w, a->ravel, next_, last, &overflow_);
    next_ = last;
    if (next_ == a->size()) ++array_, shaped_ = false;
  }
  return static_cast<std::size_t>(w - out);
}

std::string char_cards(const Workspace& ws, std::size_t* overflow) {
  CardMaker cards(ws);
  const std::size_t size = cards.size();
  std::string out;
  reserve_large(out, size + CardMaker::longest_card);
  out.resize(size + CardMaker::longest_card);
  out.resize(cards.fill(out.data(), out.size()));
  *overflow = cards.overflow();
  return out;
}

}  // namespace igds::disk
