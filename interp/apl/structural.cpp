// ⍴ , ⌽ ⊖ ⍉: shape, reshape, ravel, catenate and laminate, reverse, rotate, transpose.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "interp/apl/elements.h"
#include "interp/apl/mixed.h"

namespace igds::apl {

namespace {

// A single number (a scalar or a one-element array), for axes.
double single_number(const Value& v) {
  if (v.is_character() || v.size() != 1) domain_error();
  return v.numbers()[0];
}

// Copies `count` elements of `from` into `to`, repeating `from` as often as needed.
template <class T>
void cyclic_copy(const T* from, std::size_t from_count, T* to, std::size_t count) {
  std::size_t done = std::min(from_count, count);
  std::copy(from, from + done, to);
  while (done < count) {  // doubling the copied prefix
    std::size_t n = std::min(done, count - done);
    std::copy(to, to + n, to + done);
    done += n;
  }
}

// The element kind of a catenation: the arguments' kind; an empty argument takes the other's.
bool characters_of(const Value& a, const Value& b) {
  if (a.is_character() == b.is_character()) return a.is_character();
  if (a.empty()) return b.is_character();
  if (b.empty()) return a.is_character();
  domain_error();
}

// One argument's part of a row of the catenation: an empty argument (of the other kind) gives
// nothing, a scalar is extended, an array gives its elements from `offset`.
template <class T>
void fill_chunk(const Value& v, std::size_t offset, std::size_t n, T* out) {
  if (v.empty()) {
    std::fill(out, out + n, fill_element<T>());
  } else if (v.rank() == 0) {
    std::fill(out, out + n, elements<T>(v)[0]);
  } else {
    std::copy(elements<T>(v) + offset, elements<T>(v) + offset + n, out);
  }
}

template <class T>
Value catenate_typed(Context& ctx, const Value& a, std::size_t na, const Value& b, std::size_t nb,
                     std::size_t outer, Shape shape) {
  Value r = new_array<T>(ctx, std::move(shape));
  T* out = mutable_elements<T>(r);
  for (std::size_t o = 0; o < outer; ++o) {
    fill_chunk(a, o * na, na, out);
    fill_chunk(b, o * nb, nb, out + na);
    out += na + nb;
  }
  return r;
}

// A,[k]B for arguments of equal rank (`sa`, `sb` their shapes; a scalar takes the other's
// shape with length 1 along k, scalar extension).
Value catenate_along(Context& ctx, const Value& a, const Shape& sa, const Value& b, const Shape& sb,
                     std::size_t k) {
  for (std::size_t i = 0; i < sa.size(); ++i)
    if (i != k && sa[i] != sb[i]) length_error();
  Shape shape = sa;
  shape[k] = sa[k] + sb[k];
  const std::size_t outer = product(sa, 0, k), inner = product(sa, k + 1, sa.size());
  const std::size_t na = sa[k] * inner, nb = sb[k] * inner;
  if (characters_of(a, b)) return catenate_typed<char32_t>(ctx, a, na, b, nb, outer, shape);
  return catenate_typed<double>(ctx, a, na, b, nb, outer, shape);
}

// A scalar spread over a shape.
Value spread(Context& ctx, const Value& scalar, Shape shape) {
  return by_kind(scalar, [&](auto t) {
    using T = decltype(t);
    Value r = new_array<T>(ctx, std::move(shape));
    T* out = mutable_elements<T>(r);
    std::fill(out, out + r.size(), elements<T>(scalar)[0]);
    return r;
  });
}

// The vectors along axis k: outer × n × inner, with the element at (o, i, j) at
// (o × n + i) × inner + j.
struct Along {
  std::size_t outer, n, inner;
  Along(const Shape& shape, std::size_t k)
      : outer(product(shape, 0, k)), n(shape[k]), inner(product(shape, k + 1, shape.size())) {}
};

template <class T>
Value rotated(Context& ctx, const Value& b, std::size_t k, const std::vector<std::int64_t>& by,
              bool reverse) {
  Value r = new_array<T>(ctx, b.shape());
  const T* in = elements<T>(b);
  T* out = mutable_elements<T>(r);
  const Along al(b.shape(), k);
  if (al.n == 0) return r;
  for (std::size_t o = 0; o < al.outer; ++o) {
    for (std::size_t j = 0; j < al.inner; ++j) {
      const T* src = in + o * al.n * al.inner + j;
      T* dst = out + o * al.n * al.inner + j;
      if (reverse) {
        for (std::size_t i = 0; i < al.n; ++i) dst[i * al.inner] = src[(al.n - 1 - i) * al.inner];
        continue;
      }
      const std::int64_t s = by.size() == 1 ? by[0] : by[o * al.inner + j];
      const auto n = static_cast<std::int64_t>(al.n);
      const std::size_t shift = static_cast<std::size_t>(((s % n) + n) % n);
      for (std::size_t i = 0; i < al.n; ++i)
        dst[i * al.inner] = src[((i + shift) % al.n) * al.inner];
    }
  }
  return r;
}

// The array of shape `shape` whose element at index I is b's element at Σ I[k] × step[k].
template <class T>
Value strided_copy(Context& ctx, const Value& b, const Shape& shape,
                   const std::vector<std::size_t>& step) {
  Value r = new_array<T>(ctx, shape);
  const std::size_t n = r.size();
  if (n == 0) return r;
  const T* in = elements<T>(b);
  T* out = mutable_elements<T>(r);
  if (shape.empty()) {
    out[0] = in[0];
    return r;
  }
  const std::size_t rank = shape.size(), last = shape.back(), last_step = step.back();
  std::vector<std::size_t> at(rank, 0);
  std::size_t base = 0;
  for (std::size_t done = 0; done < n; done += last) {
    const T* src = in + base;
    for (std::size_t j = 0; j < last; ++j) out[done + j] = src[j * last_step];
    for (std::size_t k = rank - 1; k-- > 0;) {  // the odometer over the other axes
      base += step[k];
      if (++at[k] < shape[k]) break;
      base -= step[k] * at[k];
      at[k] = 0;
    }
  }
  return r;
}

}  // namespace

std::size_t axis_of(const Context& ctx, const Value* axis, std::size_t rank,
                    std::size_t otherwise) {
  if (!axis) return otherwise;
  double k = single_number(*axis);
  if (!near_integer(k)) domain_error();
  double i = std::round(k) - ctx.io;
  if (i < 0 || i >= static_cast<double>(rank)) index_error();
  return static_cast<std::size_t>(i);
}

Value shape_of(Context& ctx, const Value& b) {
  Value r = ctx.new_numbers({b.rank()});
  auto out = r.mutable_numbers();
  for (std::size_t k = 0; k < b.rank(); ++k) out[k] = static_cast<double>(b.shape()[k]);
  return r;
}

Value reshape(Context& ctx, const Value& a, const Value& b) {
  Shape shape;
  for (auto d : integer_list(a)) {
    if (d < 0) domain_error();
    shape.push_back(static_cast<std::size_t>(d));
  }
  const std::size_t n = ctx.checked_count(shape);
  if (n == b.size()) {
    ctx.charge(1);
    return b.reshaped(std::move(shape));
  }
  return by_kind(b, [&](auto t) {
    using T = decltype(t);
    Value r = new_array<T>(ctx, shape);
    T* out = mutable_elements<T>(r);
    if (b.empty()) {
      std::fill(out, out + n, fill_element<T>());  // APL2: an empty B gives fill elements
    } else {
      cyclic_copy(elements<T>(b), b.size(), out, n);
    }
    return r;
  });
}

Value ravel(Context& ctx, const Value& b, const Value* axis) {
  ctx.charge(1);
  if (!axis) return b.reshaped({b.size()});
  if (axis->is_character()) domain_error();
  auto ks = axis->numbers();
  Shape shape = b.shape();
  // ,[k] with a fractional k: a new axis of length 1 between ⌊k and ⌈k (APL2 "ravel with axis").
  if (ks.size() == 1 && !near_integer(ks[0])) {
    double pos = std::ceil(ks[0] - ctx.io);
    if (pos < 0 || pos > static_cast<double>(b.rank())) index_error();
    shape.insert(shape.begin() + static_cast<std::ptrdiff_t>(pos), 1);
    return b.reshaped(std::move(shape));
  }
  // ,[K] with contiguous axes K: those axes made one; ,[⍳0] adds a last axis of length 1.
  if (ks.empty()) {
    shape.push_back(1);
    return b.reshaped(std::move(shape));
  }
  std::size_t first = axis_of(ctx, axis->size() == 1 ? axis : nullptr, b.rank(), 0);
  if (ks.size() > 1) {
    Value k0 = Value::number(ks[0]);
    first = axis_of(ctx, &k0, b.rank(), 0);
    for (std::size_t i = 1; i < ks.size(); ++i) {
      Value ki = Value::number(ks[i]);
      if (axis_of(ctx, &ki, b.rank(), 0) != first + i) index_error();
    }
  }
  const std::size_t last = first + ks.size();
  Shape merged(shape.begin(), shape.begin() + static_cast<std::ptrdiff_t>(first));
  merged.push_back(product(shape, first, last));
  merged.insert(merged.end(), shape.begin() + static_cast<std::ptrdiff_t>(last), shape.end());
  return b.reshaped(std::move(merged));
}

Value catenate(Context& ctx, const Value& a, const Value& b, const Value* axis) {
  if (axis && !near_integer(single_number(*axis))) {
    // Laminate (APL\360 User's Manual, "laminate"): a new axis between ⌊k and ⌈k, of length 2.
    const std::size_t rank = std::max(a.rank(), b.rank());
    double pos = std::ceil(single_number(*axis) - ctx.io);
    if (pos < 0 || pos > static_cast<double>(rank)) index_error();
    const auto p = static_cast<std::size_t>(pos);
    Shape common = a.rank() >= b.rank() ? a.shape() : b.shape();
    if (a.rank() != 0 && b.rank() != 0 && a.shape() != b.shape()) {
      if (a.rank() != b.rank()) rank_error();
      length_error();
    }
    Shape s = common;
    s.insert(s.begin() + static_cast<std::ptrdiff_t>(p), 1);
    auto widened = [&](const Value& v) {
      return v.rank() == 0 && !common.empty() ? spread(ctx, v, s) : v.reshaped(s);
    };
    return catenate_along(ctx, widened(a), s, widened(b), s, p);
  }
  const std::size_t rank = std::max({a.rank(), b.rank(), std::size_t{1}});
  const std::size_t k = axis_of(ctx, axis, rank, rank - 1);
  // Each argument's shape at the result's rank: a rank one lower gets a unit axis at k.
  auto shaped = [&](const Value& v) -> std::optional<Shape> {
    if (v.rank() == 0) return std::nullopt;
    if (v.rank() == rank) return v.shape();
    if (v.rank() + 1 != rank) rank_error();
    Shape s = v.shape();
    s.insert(s.begin() + static_cast<std::ptrdiff_t>(k), 1);
    return s;
  };
  auto sa = shaped(a), sb = shaped(b);
  if (!sa && !sb) sa = sb = Shape{1};
  // A scalar takes the other's shape, one long along k (scalar extension).
  if (!sa) (sa = *sb)->at(k) = 1;
  if (!sb) (sb = *sa)->at(k) = 1;
  return catenate_along(ctx, a, *sa, b, *sb, k);
}

Value reverse(Context& ctx, const Value& b, const Value* axis, bool first_axis) {
  if (b.rank() == 0) {
    if (axis) axis_of(ctx, axis, 1, 0);
    ctx.charge(1);
    return b;
  }
  const std::size_t k = axis_of(ctx, axis, b.rank(), first_axis ? 0 : b.rank() - 1);
  return by_kind(b, [&](auto t) { return rotated<decltype(t)>(ctx, b, k, {}, true); });
}

Value rotate(Context& ctx, const Value& a, const Value& b, const Value* axis, bool first_axis) {
  std::vector<std::int64_t> by = integer_list(a.rank() <= 1 ? a : a.reshaped({a.size()}));
  if (b.rank() == 0) {
    if (by.size() != 1) length_error();
    ctx.charge(1);
    return b;
  }
  const std::size_t k = axis_of(ctx, axis, b.rank(), first_axis ? 0 : b.rank() - 1);
  if (a.size() != 1) {  // one amount per vector along k: A's shape is B's without axis k
    Shape expected = b.shape();
    expected.erase(expected.begin() + static_cast<std::ptrdiff_t>(k));
    if (a.rank() != expected.size()) rank_error();
    if (a.shape() != expected) length_error();
  }
  return by_kind(b, [&](auto t) { return rotated<decltype(t)>(ctx, b, k, by, false); });
}

Value transpose(Context& ctx, const Value& b) {
  Shape shape(b.shape().rbegin(), b.shape().rend());
  auto strides = strides_of(b.shape());
  std::vector<std::size_t> step(strides.rbegin(), strides.rend());
  return by_kind(b, [&](auto t) { return strided_copy<decltype(t)>(ctx, b, shape, step); });
}

Value transpose(Context& ctx, const Value& a, const Value& b) {
  // A⍉B (APL\360 User's Manual, "transpose"): B's axis i becomes the result's axis A[i];
  // axes mapped to the same result axis take their diagonal.
  auto order = integer_list(a);
  if (order.size() != b.rank()) length_error();
  std::size_t rank = 0;
  for (auto& k : order) {
    k -= ctx.io;
    if (k < 0 || k >= static_cast<std::int64_t>(b.rank())) domain_error();
    rank = std::max(rank, static_cast<std::size_t>(k) + 1);
  }
  Shape shape(rank, 0);
  std::vector<bool> used(rank, false);
  std::vector<std::size_t> step(rank, 0);
  auto strides = strides_of(b.shape());
  for (std::size_t i = 0; i < order.size(); ++i) {
    auto k = static_cast<std::size_t>(order[i]);
    shape[k] = used[k] ? std::min(shape[k], b.shape()[i]) : b.shape()[i];
    used[k] = true;
    step[k] += strides[i];
  }
  if (std::find(used.begin(), used.end(), false) != used.end()) domain_error();
  return by_kind(b, [&](auto t) { return strided_copy<decltype(t)>(ctx, b, shape, step); });
}

}  // namespace igds::apl
