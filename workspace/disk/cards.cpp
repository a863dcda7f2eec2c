#include "workspace/disk/cards.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>

#include "workspace/numbers/fortran.h"

namespace igds::disk {

namespace {

constexpr std::size_t per_card = 8;  // (8F10.3)
constexpr std::size_t i5 = 5, f10 = 10;

char* shape_card(char* w, const Array& a, std::size_t rank) {
  // An empty array keeps the card of its rank, all zeros, so that a reader's layout holds.
  for (std::size_t k = 0; k < rank; ++k, w += i5)
    fortran::put_i(w, k < a.shape.size() && !a.empty() ? static_cast<long long>(a.shape[k]) : 0,
                   i5);
  *w++ = '\n';
  return w;
}

// The (8F10.3) cards of values[first, last): `first` starts a card; a last card of fewer than
// eight values ends the array.
char* value_cards(char* w, std::span<const double> values, std::size_t first, std::size_t last,
                  std::size_t* overflow) {
  for (std::size_t k = first; k < last; ++k) {
    if (!fortran::put_f(w, values[k], f10, 3)) ++*overflow;
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
      for (int s : ws_.status) fortran::put_i(w, s, i5), w += i5;
      *w++ = '\n';
      for (int v : {ws_.nocur, ws_.nostr, ws_.intcu, ws_.intst}) fortran::put_i(w, v, i5), w += i5;
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
  out.resize(size + CardMaker::longest_card);
  out.resize(cards.fill(out.data(), out.size()));
  *overflow = cards.overflow();
  return out;
}

}  // namespace igds::disk
