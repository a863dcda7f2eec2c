// ↑ ↓ / \ ⌿ ⍀ and indexing: the functions that select parts of an array.
#include <algorithm>
#include <cmath>

#include "interp/apl/elements.h"
#include "interp/apl/mixed.h"

namespace igds::apl {

namespace {

// The axes named in brackets (⎕IO-based, distinct), or all axes in order.
std::vector<std::size_t> axes_of(const Context& ctx, const Value* axis, std::size_t rank) {
  std::vector<std::size_t> axes;
  if (!axis) {
    for (std::size_t k = 0; k < rank; ++k) axes.push_back(k);
    return axes;
  }
  for (auto k : integer_list(*axis)) {
    k -= ctx.io;
    if (k < 0 || k >= static_cast<std::int64_t>(rank)) index_error();
    auto u = static_cast<std::size_t>(k);
    if (std::find(axes.begin(), axes.end(), u) != axes.end()) index_error();
    axes.push_back(u);
  }
  return axes;
}

// The array of `shape` whose element at I is b's element at start+I, or the fill element where
// that falls outside b (take with overtaking, and drop).
template <class T>
Value window(Context& ctx, const Value& b, const Shape& shape,
             const std::vector<std::int64_t>& start) {
  Value r = new_array<T>(ctx, shape);
  const std::size_t n = r.size();
  T* out = mutable_elements<T>(r);
  if (n == 0) return r;
  const T* in = elements<T>(b);
  const T fill = fill_element<T>();
  const std::size_t rank = shape.size();
  if (rank == 0) {
    out[0] = b.empty() ? fill : in[0];
    return r;
  }
  const Shape& bs = b.shape();
  const auto strides = strides_of(bs);
  const std::size_t row = shape.back();
  const auto s = start.back(), nb = static_cast<std::int64_t>(bs.back());
  const auto L = static_cast<std::int64_t>(row);
  const auto j0 = static_cast<std::size_t>(std::clamp<std::int64_t>(-s, 0, L));
  const auto j1 = static_cast<std::size_t>(std::clamp<std::int64_t>(nb - s, 0, L));
  std::vector<std::size_t> at(rank, 0);
  for (std::size_t done = 0; done < n; done += row) {
    bool inside = j0 < j1;
    std::int64_t base = 0;
    for (std::size_t k = 0; k + 1 < rank && inside; ++k) {
      const std::int64_t i = start[k] + static_cast<std::int64_t>(at[k]);
      inside = i >= 0 && i < static_cast<std::int64_t>(bs[k]);
      base += i * static_cast<std::int64_t>(strides[k]);
    }
    T* o = out + done;
    if (!inside) {
      std::fill(o, o + row, fill);
    } else {
      std::fill(o, o + j0, fill);
      const T* src = in + base + s;
      std::copy(src + j0, src + j1, o + j0);
      std::fill(o + j1, o + row, fill);
    }
    for (std::size_t k = rank - 1; k-- > 0;) {
      if (++at[k] < shape[k]) break;
      at[k] = 0;
    }
  }
  return r;
}

// Take and drop: each named axis k gets a length and a start from its count c.
template <class Rule>
Value take_or_drop(Context& ctx, const Value& a, const Value& b, const Value* axis, Rule rule) {
  const auto counts = integer_list(a);
  Value bb = b.rank() == 0 ? b.reshaped(Shape(axis ? 1 : counts.size(), 1)) : b;
  const auto axes = axes_of(ctx, axis, bb.rank());
  if (counts.size() != axes.size()) length_error();
  Shape shape = bb.shape();
  std::vector<std::int64_t> start(shape.size(), 0);
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const std::size_t k = axes[i];
    const auto n = static_cast<std::int64_t>(shape[k]);
    auto [length, first] = rule(counts[i], n);
    if (length < 0) length = 0;
    shape[k] = static_cast<std::size_t>(length);
    start[k] = first;
  }
  ctx.checked_count(shape);
  return by_kind(bb, [&](auto t) { return window<decltype(t)>(ctx, bb, shape, start); });
}

// One axis of an index: the positions chosen, or all of them.
struct Pick {
  bool all = false;
  std::size_t length = 0;       // of the axis
  std::vector<std::size_t> at;  // positions when not all
  std::size_t count() const { return all ? length : at.size(); }
};

std::vector<Pick> picks_of(const Context& ctx, const Value& b,
                           const std::vector<std::optional<Value>>& indices, Shape& shape) {
  if (indices.size() != b.rank()) rank_error();
  std::vector<Pick> picks(indices.size());
  shape.clear();
  for (std::size_t k = 0; k < indices.size(); ++k) {
    Pick& p = picks[k];
    p.length = b.shape()[k];
    if (!indices[k]) {
      p.all = true;
      shape.push_back(p.length);
      continue;
    }
    const Value& i = *indices[k];
    shape.insert(shape.end(), i.shape().begin(), i.shape().end());
    if (i.is_character()) {
      if (i.empty()) continue;
      domain_error();
    }
    p.at.reserve(i.size());
    for (double x : i.numbers()) {
      if (!near_integer(x)) domain_error();
      const double pos = std::round(x) - ctx.io;
      if (pos < 0 || pos >= static_cast<double>(p.length)) index_error();
      p.at.push_back(static_cast<std::size_t>(pos));
    }
  }
  return picks;
}

// Calls row(base, to, offsets, step, block) for each row of the selection, in the result's
// order: for each j, the `block` consecutive elements at base + offsets[j] are the result's
// elements from to + j × block; when the row's axis is taken whole, offsets[j] is j × step
// (step is 0 otherwise). Trailing whole axes make the blocks long; axes with a single position
// are folded into the base, so that INTPN[;;1] runs one tight loop per row of INTPN.
template <class Row>
void for_each_row(const Shape& bs, const std::vector<Pick>& picks, Row row) {
  const std::size_t rank = bs.size();
  const auto strides = strides_of(bs);
  std::size_t t = rank, block = 1;
  while (t > 0 && picks[t - 1].all) {
    --t;
    block *= bs[t];
  }
  std::size_t base = 0;
  std::vector<std::size_t> loop;
  for (std::size_t k = 0; k < t; ++k) {
    if (picks[k].count() == 0) return;
    if (!picks[k].all && picks[k].count() == 1) {
      base += picks[k].at[0] * strides[k];
    } else {
      loop.push_back(k);
    }
  }
  if (block == 0) return;
  if (loop.empty()) {
    row(base, 0, std::vector<std::size_t>{0}, 0, block);
    return;
  }
  std::vector<std::vector<std::size_t>> off;
  for (auto k : loop) {
    std::vector<std::size_t> o(picks[k].count());
    for (std::size_t j = 0; j < o.size(); ++j)
      o[j] = (picks[k].all ? j : picks[k].at[j]) * strides[k];
    off.push_back(std::move(o));
  }
  const std::size_t m = loop.size(), per_row = off.back().size() * block;
  const std::size_t step = picks[loop.back()].all ? strides[loop.back()] : 0;
  std::vector<std::size_t> at(m, 0);
  for (std::size_t to = 0;; to += per_row) {
    std::size_t here = base;
    for (std::size_t i = 0; i + 1 < m; ++i) here += off[i][at[i]];
    row(here, to, off.back(), step, block);
    std::size_t i = m - 1;
    while (i-- > 0) {
      if (++at[i] < off[i].size()) break;
      at[i] = 0;
    }
    if (i == static_cast<std::size_t>(-1)) return;
  }
}

// The shape without its axes of length 1 (to compare the shapes of B[I] and C in B[I]←C).
Shape without_units(const Shape& s) {
  Shape r;
  for (auto d : s)
    if (d != 1) r.push_back(d);
  return r;
}

}  // namespace

Value take(Context& ctx, const Value& a, const Value& b, const Value* axis) {
  // A↑B (APL\360 User's Manual, "take"): |A[k] elements of axis k, from the end when A[k] is
  // negative; beyond the length, fill elements (0 or blank).
  return take_or_drop(ctx, a, b, axis, [](std::int64_t c, std::int64_t n) {
    return std::pair<std::int64_t, std::int64_t>{c >= 0 ? c : -c, c >= 0 ? 0 : n + c};
  });
}

Value drop(Context& ctx, const Value& a, const Value& b, const Value* axis) {
  return take_or_drop(ctx, a, b, axis, [](std::int64_t c, std::int64_t n) {
    const std::int64_t m = c >= 0 ? c : -c;
    return std::pair<std::int64_t, std::int64_t>{n - m, c >= 0 ? std::min(c, n) : 0};
  });
}

Value replicate(Context& ctx, const Value& a, const Value& b, const Value* axis, bool first_axis) {
  // A/B (APL\360 "compression"; APL2 "replicate"): A[i] copies of the i-th item along the axis,
  // a negative A[i] giving that many fill items.
  auto counts = integer_list(a);
  const Value bb = b.rank() == 0 ? b.reshaped({1}) : b;
  const std::size_t k = axis_of(ctx, axis, bb.rank(), first_axis ? 0 : bb.rank() - 1);
  const std::size_t n = bb.shape()[k];
  if (counts.size() == 1 && n != 1) counts.assign(n, counts[0]);
  const bool spread = n == 1 && counts.size() != 1;
  if (!spread && counts.size() != n) length_error();
  std::size_t total = 0;
  for (auto c : counts) {
    total += static_cast<std::size_t>(c < 0 ? -c : c);
    if (total > ctx.limits.max_elements) throw Error(ErrorKind::ws_full);
  }
  Shape shape = bb.shape();
  shape[k] = total;
  const std::size_t outer = product(shape, 0, k), inner = product(shape, k + 1, shape.size());
  return by_kind(bb, [&](auto t) {
    using T = decltype(t);
    Value r = new_array<T>(ctx, shape);
    const T* in = elements<T>(bb);
    T* out = mutable_elements<T>(r);
    for (std::size_t o = 0; o < outer; ++o) {
      for (std::size_t i = 0; i < counts.size(); ++i) {
        const T* src = in + (o * n + (spread ? 0 : i)) * inner;
        for (std::int64_t c = 0; c < std::abs(counts[i]); ++c) {
          if (counts[i] > 0) {
            out = std::copy(src, src + inner, out);
          } else {
            out = std::fill_n(out, inner, fill_element<T>());
          }
        }
      }
    }
    return r;
  });
}

Value expand(Context& ctx, const Value& a, const Value& b, const Value* axis, bool first_axis) {
  // A\B (APL\360 User's Manual, "expansion"): B's items where A has 1, fill items where 0.
  const auto mask = integer_list(a);
  const Value bb = b.rank() == 0 ? b.reshaped({1}) : b;
  const std::size_t k = axis_of(ctx, axis, bb.rank(), first_axis ? 0 : bb.rank() - 1);
  const std::size_t n = bb.shape()[k];
  std::size_t ones = 0;
  for (auto m : mask) {
    if (m != 0 && m != 1) domain_error();
    ones += static_cast<std::size_t>(m);
  }
  const bool spread = n == 1 && ones != 1;
  if (!spread && ones != n) length_error();
  Shape shape = bb.shape();
  shape[k] = mask.size();
  const std::size_t outer = product(shape, 0, k), inner = product(shape, k + 1, shape.size());
  return by_kind(bb, [&](auto t) {
    using T = decltype(t);
    Value r = new_array<T>(ctx, shape);
    const T* in = elements<T>(bb);
    T* out = mutable_elements<T>(r);
    for (std::size_t o = 0; o < outer; ++o) {
      std::size_t j = 0;
      for (auto m : mask) {
        if (m) {
          const T* src = in + (o * n + (spread ? 0 : j++)) * inner;
          out = std::copy(src, src + inner, out);
        } else {
          out = std::fill_n(out, inner, fill_element<T>());
        }
      }
    }
    return r;
  });
}

Value index(Context& ctx, const Value& b, const std::vector<std::optional<Value>>& indices) {
  Shape shape;
  const auto picks = picks_of(ctx, b, indices, shape);
  return by_kind(b, [&](auto t) {
    using T = decltype(t);
    Value r = new_array<T>(ctx, shape);
    const T* in = elements<T>(b);
    T* out = mutable_elements<T>(r);
    for_each_row(b.shape(), picks,
                 [&](std::size_t base, std::size_t to, const std::vector<std::size_t>& offsets,
                     std::size_t step, std::size_t block) {
                   const T* src = in + base;
                   T* dst = out + to;
                   const std::size_t n = offsets.size();
                   if (block == 1 && step != 0) {  // a whole axis: a strided loop
                     for (std::size_t j = 0; j < n; ++j) dst[j] = src[j * step];
                   } else if (block == 1) {
                     for (std::size_t j = 0; j < n; ++j) dst[j] = src[offsets[j]];
                   } else {
                     for (std::size_t j = 0; j < n; ++j)
                       std::copy(src + offsets[j], src + offsets[j] + block, dst + j * block);
                   }
                 });
    return r;
  });
}

void index_assign(Context& ctx, Value& b, const std::vector<std::optional<Value>>& indices,
                  const Value& c) {
  Shape shape;
  const auto picks = picks_of(ctx, b, indices, shape);
  const std::size_t n = element_count(shape);
  const bool single = c.size() == 1;
  if (!single && without_units(c.shape()) != without_units(shape)) {
    // One element chosen takes one value; otherwise the shapes (unit axes aside) agree.
    if (n != 1 && without_units(c.shape()).size() != without_units(shape).size()) rank_error();
    length_error();
  }
  if (n == 0) return;
  if (c.is_character() != b.is_character()) domain_error();
  ctx.charge(n);
  by_kind(b, [&](auto t) {
    using T = decltype(t);
    T* out = mutable_elements<T>(b);
    const T* in = elements<T>(c);
    for_each_row(b.shape(), picks,
                 [&](std::size_t base, std::size_t from, const std::vector<std::size_t>& offsets,
                     std::size_t, std::size_t block) {
                   T* dst = out + base;
                   for (std::size_t j = 0; j < offsets.size(); ++j) {
                     T* d = dst + offsets[j];
                     if (single) {
                       std::fill(d, d + block, in[0]);
                     } else {
                       std::copy(in + from + j * block, in + from + (j + 1) * block, d);
                     }
                   }
                 });
    return 0;
  });
}

}  // namespace igds::apl
