// ⍳ ∊ ~ ⍋ ⍒ ?: index generator and index of, membership, without, grades and deal.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "interp/apl/elements.h"
#include "interp/apl/mixed.h"

namespace igds::apl {

namespace {

constexpr std::size_t not_found = static_cast<std::size_t>(-1);

// The first position of each element in a list, found with the comparison tolerance: by a scan
// when the list is short, by binary search among its sorted distinct values otherwise.
class Finder {
 public:
  Finder(const Value& list, const Context& ctx) : list_(list), ct_(ctx.ct) {
    const std::size_t n = list.size();
    if (n <= 16) return;
    sorted_.resize(n);
    std::iota(sorted_.begin(), sorted_.end(), std::size_t{0});
    if (list.is_character()) {
      auto c = list.characters();
      for (std::size_t i = n; i-- > 0;) first_char_[c[i]] = i;
      return;
    }
    auto x = list.numbers();
    std::stable_sort(sorted_.begin(), sorted_.end(),
                     [&](std::size_t i, std::size_t j) { return x[i] < x[j]; });
    // Keep the first position of each distinct value: a run of equal values costs one probe.
    sorted_.erase(std::unique(sorted_.begin(), sorted_.end(),
                              [&](std::size_t i, std::size_t j) { return x[i] == x[j]; }),
                  sorted_.end());
    values_.reserve(sorted_.size());
    for (auto i : sorted_) values_.push_back(x[i]);
  }

  std::size_t find_number(double v) const {
    if (list_.is_character()) return not_found;
    auto x = list_.numbers();
    if (values_.empty()) {
      for (std::size_t i = 0; i < x.size(); ++i)
        if (tolerant_equal(x[i], v, ct_)) return i;
      return not_found;
    }
    // |v-y| ≤ ⎕CT×(|v|⌈|y|) implies |v-y| ≤ 2×⎕CT×|v| while ⎕CT < 0.5.
    const double tol = 2 * ct_ * std::fabs(v);
    auto it = std::lower_bound(values_.begin(), values_.end(), v - tol);
    std::size_t best = not_found;
    for (; it != values_.end() && *it <= v + tol; ++it) {
      if (tolerant_equal(*it, v, ct_))
        best = std::min(best, sorted_[static_cast<std::size_t>(it - values_.begin())]);
    }
    return best;
  }

  std::size_t find_character(char32_t c) const {
    if (list_.is_numeric()) return not_found;
    if (sorted_.empty()) {
      auto x = list_.characters();
      for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i] == c) return i;
      return not_found;
    }
    auto it = first_char_.find(c);
    return it == first_char_.end() ? not_found : it->second;
  }

  // The position of element i of v.
  std::size_t find(const Value& v, std::size_t i) const {
    return v.is_character() ? find_character(v.characters()[i]) : find_number(v.numbers()[i]);
  }

 private:
  const Value& list_;
  double ct_;
  std::vector<std::size_t> sorted_;
  std::vector<double> values_;
  std::unordered_map<char32_t, std::size_t> first_char_;
};

// The permutation that sorts the major cells of b by `less` on their elements (lexicographic
// over each cell), ties in their original order.
template <class T, class Key>
std::vector<std::size_t> grade_cells(const Value& b, bool up, Key key) {
  const std::size_t n = b.shape()[0], cell = n == 0 ? 0 : b.size() / n;
  const T* x = elements<T>(b);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    for (std::size_t k = 0; k < cell; ++k) {
      auto p = key(x[i * cell + k]), q = key(x[j * cell + k]);
      if (p != q) return up ? p < q : p > q;
    }
    return false;
  });
  return order;
}

Value indices_value(Context& ctx, const std::vector<std::size_t>& order) {
  Value r = ctx.new_numbers({order.size()});
  auto out = r.mutable_numbers();
  for (std::size_t i = 0; i < order.size(); ++i) out[i] = static_cast<double>(order[i] + ctx.io);
  return r;
}

double single(const Value& v) {
  if (v.is_character()) domain_error();
  if (v.size() != 1) {
    if (v.rank() > 1) rank_error();
    length_error();
  }
  return v.numbers()[0];
}

}  // namespace

Value iota(Context& ctx, const Value& b) {
  if (b.rank() > 1) rank_error();
  const std::size_t n = count_of(single(b));
  Value r = ctx.new_numbers({n});
  auto out = r.mutable_numbers();
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<double>(i + ctx.io);
  return r;
}

Value index_of(Context& ctx, const Value& a, const Value& b) {
  // A⍳B (APL\360 User's Manual, "index of"): the first position of each element of B in the
  // vector A, or ⎕IO+⍴A where it is absent.
  if (a.rank() > 1) rank_error();
  Finder finder(a, ctx);
  Value r = ctx.new_numbers(b.shape());
  auto out = r.mutable_numbers();
  ctx.charge(a.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    std::size_t at = finder.find(b, i);
    out[i] = static_cast<double>((at == not_found ? a.size() : at) + ctx.io);
  }
  return r;
}

Value member_of(Context& ctx, const Value& a, const Value& b) {
  Finder finder(b, ctx);
  Value r = ctx.new_numbers(a.shape());
  auto out = r.mutable_numbers();
  ctx.charge(b.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = finder.find(a, i) != not_found;
  return r;
}

Value without(Context& ctx, const Value& a, const Value& b) {
  // A~B (APL2 Language Reference, "without"): the elements of the vector A not in B.
  if (a.rank() > 1) rank_error();
  Finder finder(b, ctx);
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (finder.find(a, i) == not_found) kept.push_back(i);
  return by_kind(a, [&](auto t) {
    using T = decltype(t);
    Value r = new_array<T>(ctx, {kept.size()});
    T* out = mutable_elements<T>(r);
    for (std::size_t i = 0; i < kept.size(); ++i) out[i] = elements<T>(a)[kept[i]];
    return r;
  });
}

Value grade(Context& ctx, const Value& b, bool up) {
  if (b.rank() == 0) rank_error();
  ctx.charge(b.size() * 4 + 1);
  auto order = by_kind(b, [&](auto t) {
    using T = decltype(t);
    return grade_cells<T>(b, up, [](T v) { return v; });
  });
  return indices_value(ctx, order);
}

Value grade(Context& ctx, const Value& a, const Value& b, bool up) {
  // A⍋B with a character vector A: the characters of B ordered by their position in A
  // (APL.SV "dyadic grade"); characters absent from A come after all of A's.
  if (a.rank() != 1) rank_error();
  if (b.rank() == 0) rank_error();
  if (!a.is_character() || !b.is_character()) domain_error();
  ctx.charge(b.size() * 4 + a.size());
  std::unordered_map<char32_t, std::size_t> rank_of;
  auto seq = a.characters();
  for (std::size_t i = seq.size(); i-- > 0;) rank_of[seq[i]] = i;
  auto order = grade_cells<char32_t>(b, up, [&](char32_t c) {
    auto it = rank_of.find(c);
    return it == rank_of.end() ? seq.size() : it->second;
  });
  return indices_value(ctx, order);
}

Value deal(Context& ctx, const Value& a, const Value& b) {
  // A?B (APL\360 User's Manual, "deal"): A distinct integers chosen at random from ⍳B, by a
  // partial Fisher-Yates shuffle (sparse when B is much larger than A).
  const std::size_t count = count_of(single(a)), range = count_of(single(b));
  if (count > range) domain_error();
  Value r = ctx.new_numbers({count});
  auto out = r.mutable_numbers();
  if (range <= std::max<std::size_t>(4 * count, 1024) && range <= ctx.limits.max_elements) {
    ctx.charge(range);
    std::vector<std::size_t> pool(range);
    std::iota(pool.begin(), pool.end(), std::size_t{0});
    for (std::size_t i = 0; i < count; ++i) {
      auto j = i + static_cast<std::size_t>(std::floor(ctx.random() * double(range - i)));
      std::swap(pool[i], pool[std::min(j, range - 1)]);
      out[i] = static_cast<double>(pool[i] + ctx.io);
    }
    return r;
  }
  std::unordered_map<std::size_t, std::size_t> moved;
  auto at = [&](std::size_t i) {
    auto it = moved.find(i);
    return it == moved.end() ? i : it->second;
  };
  for (std::size_t i = 0; i < count; ++i) {
    auto j = i + static_cast<std::size_t>(std::floor(ctx.random() * double(range - i)));
    j = std::min(j, range - 1);
    std::size_t pi = at(i), pj = at(j);
    moved[i] = pj;
    moved[j] = pi;
    out[i] = static_cast<double>(pj + ctx.io);
  }
  return r;
}

}  // namespace igds::apl
