#include "workspace/exchange/marks_deck.h"

#include <cassert>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "workspace/kernels/limits.h"
#include "workspace/kernels/marks.h"
#include "workspace/numbers/fortran.h"

namespace igds::exchange {

namespace {

constexpr std::size_t keys_per_card = 18;  // (18F4.0)
constexpr std::size_t key_width = 4;
constexpr std::size_t values_per_card = 9;  // (9F7.1)
constexpr std::size_t value_width = 7;
constexpr int value_decimals = 1;

// The lines of a text as cards: a line ends at LF (a CR before it is dropped); a last line without
// LF is a card too.
class Cards {
 public:
  explicit Cards(std::string_view text) : text_(text) {}
  // The next card into `card`; false at the end of the text.
  bool next(std::string_view& card) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    card = text_.substr(pos_, end - pos_);
    if (!card.empty() && card.back() == '\r') card.remove_suffix(1);
    pos_ = end + 1;
    ++line_;
    return true;
  }
  // The line number of the card last returned (1-based; 0 before the first).
  std::size_t line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0, line_ = 0;
};

DeckError at(DeckError::Problem problem, std::size_t line, std::size_t column = 0) {
  DeckError e(problem);
  e.line = line;
  e.column = column;
  return e;
}

// Reads fields of one format from consecutive cards, a new card when the format is used up
// (FORTRAN's format reversion) or when `restart` asks for one (a new READ).
class FieldReader {
 public:
  FieldReader(Cards& cards, std::size_t per_card, std::size_t width, int decimals)
      : cards_(cards), per_card_(per_card), width_(width), used_(per_card), decimals_(decimals) {}
  void restart() { used_ = per_card_; }
  double next() {
    if (used_ == per_card_) {
      if (!cards_.next(card_)) throw at(DeckError::Problem::ends_early, cards_.line() + 1);
      used_ = 0;
    }
    const std::size_t first = used_++ * width_;
    const auto value = fortran::read_f(card_, first, width_, decimals_);
    if (!value) throw at(DeckError::Problem::bad_number, cards_.line(), first + 1);
    column_ = first + 1;
    return *value;
  }
  std::size_t column() const { return column_; }  // of the field last read, 1-based

 private:
  Cards& cards_;
  std::string_view card_;
  std::size_t per_card_, width_, used_, column_ = 0;
  int decimals_;
};

}  // namespace

const char* DeckError::what() const noexcept {
  try {
    switch (problem) {
      case Problem::bad_number:
        text_ = fmt::format("line {} column {}: not a number", line, column);
        break;
      case Problem::bad_key:
        text_ = fmt::format("line {} column {}: the key of point {} is not 0 to 15", line, column,
                            point);
        break;
      case Problem::missing_point:
        text_ = fmt::format("point {} has no position (line {})", point, line);
        break;
      case Problem::ends_early:
        text_ = fmt::format("the deck ends before line {}", line);
        break;
      case Problem::extra_cards:
        text_ = fmt::format("line {}: a card after the last point", line);
        break;
      case Problem::too_small:
        text_ = fmt::format("{} rows and {} columns: fewer than 2", rows, columns);
        break;
      case Problem::too_large:
        text_ = fmt::format("{} rows and {} columns: too many points", rows, columns);
        break;
    }
  } catch (...) {
    return "deck error";
  }
  return text_.c_str();
}

MarksDeck read_deck(std::string_view text) {
  Cards cards(text);
  std::string_view card;
  // (2I4) MR, NC.
  if (!cards.next(card)) throw at(DeckError::Problem::ends_early, 1);
  const auto rows = fortran::read_i(card, 0, 4);
  if (!rows) throw at(DeckError::Problem::bad_number, 1, 1);
  const auto columns = fortran::read_i(card, 4, 4);
  if (!columns) throw at(DeckError::Problem::bad_number, 1, 5);
  if (*rows < 2 || *columns < 2 || *rows * *columns > static_cast<long long>(max_input_points)) {
    DeckError e(*rows < 2 || *columns < 2 ? DeckError::Problem::too_small
                                          : DeckError::Problem::too_large);
    e.line = 1;
    e.rows = *rows;
    e.columns = *columns;
    throw e;
  }
  MarksDeck deck;
  deck.rows = int(*rows);
  deck.columns = int(*columns);
  const std::size_t n = std::size_t(*rows) * std::size_t(*columns);
  // (18F4.0) the keys, row by row. Storage grows with what is read, so that a deck that claims
  // many points but ends early costs no more than its own size.
  FieldReader keys(cards, keys_per_card, key_width, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const double key = keys.next();
    if (!(key >= 0 && key <= 15 && key == std::floor(key))) {
      DeckError e = at(DeckError::Problem::bad_key, cards.line(), keys.column());
      e.point = k + 1;
      throw e;
    }
    if ((int(key) & key_position) == 0) {
      DeckError e = at(DeckError::Problem::missing_point, cards.line(), keys.column());
      e.point = k + 1;
      throw e;
    }
    deck.keys.push_back(int(key));
  }
  // (9F7.1) each point on a new card: x y z, then the given vectors H, V, T in that order.
  Ravel points, given[3];
  FieldReader values(cards, values_per_card, value_width, value_decimals);
  for (std::size_t k = 0; k < n; ++k) {
    values.restart();
    for (int c = 0; c < 3; ++c) points.push_back(values.next());
    for (int v = 0; v < 3; ++v) {
      const bool is_given = (deck.keys[k] & (key_horizontal << v)) != 0;
      for (int c = 0; c < 3; ++c) given[v].push_back(is_given ? values.next() : 0.0);
    }
  }
  // Nothing may follow but blank cards: more means MR, NC or the keys do not describe the deck.
  while (cards.next(card)) {
    if (card.find_first_not_of(' ') != std::string_view::npos)
      throw at(DeckError::Problem::extra_cards, cards.line());
  }
  auto array = [n](Ravel&& v) {
    Array a;
    a.shape = {n, 3};
    a.ravel = std::move(v);
    return a;
  };
  deck.points = array(std::move(points));
  deck.horizontal = array(std::move(given[0]));
  deck.vertical = array(std::move(given[1]));
  deck.twists = array(std::move(given[2]));
  return deck;
}

MarksFit fit_deck(const MarksDeck& deck) {
  const int mr = deck.rows, nc = deck.columns;
  const std::size_t n = std::size_t(mr) * std::size_t(nc);
  assert(mr >= 2 && nc >= 2 && deck.keys.size() == n && deck.points.size() == 3 * n);
  const auto points = as_vec3(deck.points);
  MarksFit fit;
  fit.tangents = marks_grid_tangents(mr, nc, points);
  fit.twists = marks_twists(mr, nc, points);
  // The deck's vectors replace Marks's at their points only: Marks computes the others from the
  // points (HORTANV "looks two points on either side"), not from given neighbours.
  auto twists = as_vec3(fit.twists);
  for (std::size_t k = 0; k < n; ++k) {
    const int key = deck.keys[k];
    if (key & key_horizontal) fit.tangents.along_curves[k] = as_vec3(deck.horizontal)[k];
    if (key & key_vertical) fit.tangents.along_stringers[k] = as_vec3(deck.vertical)[k];
    if (key & key_twist) twists[k] = as_vec3(deck.twists)[k];
  }
  coons_patches(mr, nc, points, fit.tangents, fit.patches, as_vec3(std::as_const(fit.twists)));
  fit.inptg = border_tangents_of(mr, nc, points, fit.tangents);
  return fit;
}

}  // namespace igds::exchange
