#include "workspace/disk/cards.h"

#include <algorithm>
#include <atomic>
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

}  // namespace

std::size_t put_char_cards(const Workspace& ws, TextOut& out) {
  // (10I5), (4I5), then a shape card and the value cards of each array.
  char* w = out.room(ws.status.size() * i5 + 1);
  for (int s : ws.status) fortran::put_i(w, s, i5), w += i5;
  *w++ = '\n';
  out.commit(w);
  w = out.room(4 * i5 + 1);
  for (int v : {ws.nocur, ws.nostr, ws.intcu, ws.intst}) fortran::put_i(w, v, i5), w += i5;
  *w++ = '\n';
  out.commit(w);
  std::atomic<std::size_t> overflow = 0;
  Array made;
  for (const auto& array :
       {std::pair{&ws.inppn, 2}, {&ws.inptg, 2}, {&ws.intpn, 3}, {&patches_of(ws, made), 5}}) {
    const Array* a = array.first;
    const auto rank = std::size_t(array.second);
    out.commit(shape_card(out.room(rank * i5 + 1), *a, rank));
    const std::size_t cards = (a->size() + per_card - 1) / per_card;
    put_each(out, cards, longest_card, [&](char* w, std::size_t k) {
      std::size_t asterisks = 0;
      w = value_cards(w, a->ravel, k * per_card, std::min(a->size(), (k + 1) * per_card),
                      &asterisks);
      if (asterisks > 0) overflow += asterisks;
      return w;
    });
  }
  return overflow;
}

std::string char_cards(const Workspace& ws, std::size_t* overflow) {
  StringOut out;
  *overflow = put_char_cards(ws, out);
  return out.take_text();
}

}  // namespace igds::disk
