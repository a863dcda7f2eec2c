#include "interp/apl/operators.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "interp/apl/elements.h"
#include "interp/apl/mixed.h"
#include "interp/apl/scalar.h"

namespace igds::apl {

namespace {

void check_finite(double x) {
  if (!(std::fabs(x) <= DBL_MAX)) domain_error();
}

// +/ of a contiguous row: eight running sums, so that the loop runs at memory speed.
double sum(const double* x, std::size_t n) {
  double s[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
    for (std::size_t j = 0; j < 8; ++j) s[j] += x[i + j];
  double t = 0;
  for (; i < n; ++i) t += x[i];
  return ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7])) + t;
}

// f/ of a contiguous row of n ≥ 1 numbers.
double fold(const Context& ctx, char32_t f, const DyadicLoops& loops, const double* x,
            std::size_t n) {
  switch (f) {
    case U'+': {
      double s = sum(x, n);
      check_finite(s);
      return s;
    }
    case U'⌈':
      return *std::max_element(x, x + n);
    case U'⌊':
      return *std::min_element(x, x + n);
    default:
      break;
  }
  double acc = x[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) acc = loops.one(ctx, x[i], acc);
  return acc;
}

// The result of f/ or f\ over characters: only = and ≠ apply, and a character compared with
// the number of a previous comparison is never equal to it.
double fold_characters(char32_t f, const char32_t* x, std::size_t n, std::size_t step) {
  if (f != U'=' && f != U'≠') domain_error();
  const bool differ = f == U'≠';
  if (n == 2) return (x[0] != x[step]) == differ;
  return differ;
}

Value identity_fill(Context& ctx, char32_t f, Shape shape) {
  auto id = identity_element(f);
  if (!id) domain_error();
  Value r = ctx.new_numbers(std::move(shape));
  auto out = r.mutable_numbers();
  std::fill(out.begin(), out.end(), *id);
  return r;
}

struct Along {
  std::size_t outer, n, inner;
  Along(const Shape& shape, std::size_t k)
      : outer(product(shape, 0, k)), n(shape[k]), inner(product(shape, k + 1, shape.size())) {}
};

// C = A B for A m×n and B n×p (row-major), four rows of C at a time over blocks of B that stay
// in the cache; the innermost loop runs along rows of B and C (contiguous, vectorised). Each
// block's multiplications are charged as it starts, so that a long product can be interrupted.
void matrix_product(Context& ctx, const double* a, const double* b, double* c, std::size_t m,
                    std::size_t n, std::size_t p) {
  constexpr std::size_t jb = 256, kb = 128;
  std::fill(c, c + m * p, 0.0);
  for (std::size_t jj = 0; jj < p; jj += jb) {
    const std::size_t jn = std::min(jb, p - jj);
    for (std::size_t kk = 0; kk < n; kk += kb) {
      const std::size_t kn = std::min(kb, n - kk);
      ctx.charge(m * jn * kn);
      std::size_t i = 0;
      for (; i + 4 <= m; i += 4) {
        double* __restrict c0 = c + i * p + jj;
        double* __restrict c1 = c0 + p;
        double* __restrict c2 = c1 + p;
        double* __restrict c3 = c2 + p;
        for (std::size_t k = kk; k < kk + kn; ++k) {
          const double a0 = a[i * n + k], a1 = a[(i + 1) * n + k], a2 = a[(i + 2) * n + k],
                       a3 = a[(i + 3) * n + k];
          const double* __restrict bk = b + k * p + jj;
          for (std::size_t j = 0; j < jn; ++j) {
            const double x = bk[j];
            c0[j] += a0 * x;
            c1[j] += a1 * x;
            c2[j] += a2 * x;
            c3[j] += a3 * x;
          }
        }
      }
      for (; i < m; ++i) {
        double* __restrict ci = c + i * p + jj;
        for (std::size_t k = kk; k < kk + kn; ++k) {
          const double ai = a[i * n + k];
          const double* __restrict bk = b + k * p + jj;
          for (std::size_t j = 0; j < jn; ++j) ci[j] += ai * bk[j];
        }
      }
    }
  }
}

}  // namespace

Value reduce(Context& ctx, char32_t f, const Value& b, const Value* axis, bool first_axis) {
  if (b.rank() == 0) {
    axis_of(ctx, axis, 1, 0);
    ctx.charge(1);
    return b;
  }
  const std::size_t k = axis_of(ctx, axis, b.rank(), first_axis ? 0 : b.rank() - 1);
  const Along al(b.shape(), k);
  Shape shape = b.shape();
  shape.erase(shape.begin() + static_cast<std::ptrdiff_t>(k));
  if (al.n == 1) {
    ctx.charge(b.size());
    return b.reshaped(std::move(shape));
  }
  if (al.n == 0) return identity_fill(ctx, f, std::move(shape));
  Value r = ctx.new_numbers(std::move(shape));
  double* out = r.mutable_numbers().data();
  ctx.charge(b.size());
  if (b.is_character()) {
    const char32_t* x = b.characters().data();
    for (std::size_t o = 0; o < al.outer; ++o)
      for (std::size_t j = 0; j < al.inner; ++j)
        out[o * al.inner + j] = fold_characters(f, x + o * al.n * al.inner + j, al.n, al.inner);
    return r;
  }
  const DyadicLoops& loops = dyadic_loops(f);
  const double* x = b.numbers().data();
  if (al.inner == 1) {
    for (std::size_t o = 0; o < al.outer; ++o) out[o] = fold(ctx, f, loops, x + o * al.n, al.n);
    return r;
  }
  // Along an outer axis: whole rows combined from the last one back, f(row i, accumulated).
  for (std::size_t o = 0; o < al.outer; ++o) {
    const double* rows = x + o * al.n * al.inner;
    double* acc = out + o * al.inner;
    std::copy(rows + (al.n - 1) * al.inner, rows + al.n * al.inner, acc);
    for (std::size_t i = al.n - 1; i-- > 0;) loops.vv(ctx, rows + i * al.inner, acc, acc, al.inner);
  }
  return r;
}

Value scan(Context& ctx, char32_t f, const Value& b, const Value* axis, bool first_axis) {
  // f\B (APL\360 User's Manual, "scan"): element i is f/ of the first i+1 elements.
  if (b.rank() == 0) {
    axis_of(ctx, axis, 1, 0);
    ctx.charge(1);
    return b;
  }
  const std::size_t k = axis_of(ctx, axis, b.rank(), first_axis ? 0 : b.rank() - 1);
  const Along al(b.shape(), k);
  if (al.n <= 1 || b.empty()) {
    ctx.charge(b.size());
    return b;
  }
  if (b.is_character()) domain_error();  // the result would mix characters and numbers
  const DyadicLoops& loops = dyadic_loops(f);
  const double* x = b.numbers().data();
  bool zero = false;
  if (f == U'÷')
    for (std::size_t i = 0; i < b.size() && !zero; ++i) zero = x[i] == 0;
  const bool associative = loops.associative;
  const bool alternating = f == U'-' || (f == U'÷' && !zero);
  if (!associative && !alternating) ctx.charge(b.size() * (al.n + 1) / 2);
  Value r = ctx.new_numbers(b.shape());
  double* out = r.mutable_numbers().data();
  const std::size_t row = al.n * al.inner;
  const DyadicLoops& plus = dyadic_loops(U'+');
  const DyadicLoops& times = dyadic_loops(U'×');
  const DyadicLoops& minus = dyadic_loops(U'-');
  const DyadicLoops& divide = dyadic_loops(U'÷');
  for (std::size_t o = 0; o < al.outer; ++o) {
    const double* in = x + o * row;
    double* res = out + o * row;
    std::copy(in, in + al.inner, res);
    for (std::size_t i = 1; i < al.n; ++i) {
      const double* prev = res + (i - 1) * al.inner;
      const double* xi = in + i * al.inner;
      double* ri = res + i * al.inner;
      if (associative) {
        loops.vv(ctx, prev, xi, ri, al.inner);
      } else if (f == U'-') {  // x0-x1+x2-...: the signs alternate
        (i % 2 ? minus : plus).vv(ctx, prev, xi, ri, al.inner);
      } else if (alternating) {  // x0÷x1×x2÷...
        (i % 2 ? divide : times).vv(ctx, prev, xi, ri, al.inner);
      } else {  // the definition itself: f/ of the first i+1, from the right
        std::copy(xi, xi + al.inner, ri);
        for (std::size_t m = i; m-- > 0;) loops.vv(ctx, in + m * al.inner, ri, ri, al.inner);
      }
    }
  }
  return r;
}

Value outer_product(Context& ctx, char32_t f, const Value& a, const Value& b) {
  Shape shape = a.shape();
  shape.insert(shape.end(), b.shape().begin(), b.shape().end());
  Value r = ctx.new_numbers(std::move(shape));
  double* out = r.mutable_numbers().data();
  const std::size_t na = a.size(), nb = b.size();
  for (std::size_t i = 0; i < na; ++i) dyadic_scalar_row(ctx, f, a, i, b, 0, nb, out + i * nb);
  return r;
}

Value inner_product(Context& ctx, char32_t f, char32_t g, const Value& a, const Value& b) {
  // A f.g B (APL\360 User's Manual, "inner product"): f/ of A's rows g B's columns; the last
  // axis of A and the first of B agree, or one of them is of length 1 (extended).
  const std::size_t la = a.rank() == 0 ? 1 : a.shape().back();
  const std::size_t lb = b.rank() == 0 ? 1 : b.shape().front();
  if (la != lb && la != 1 && lb != 1) length_error();
  const std::size_t n = (la == 0 || lb == 0) ? 0 : std::max(la, lb);
  Shape shape;
  if (a.rank() > 0) shape.assign(a.shape().begin(), a.shape().end() - 1);
  const std::size_t m = element_count(shape);
  if (b.rank() > 0) shape.insert(shape.end(), b.shape().begin() + 1, b.shape().end());
  const std::size_t p = b.rank() > 0 ? product(b.shape(), 1, b.rank()) : 1;
  if (n == 0) return identity_fill(ctx, f, std::move(shape));
  Value r = ctx.new_numbers(std::move(shape));
  double* out = r.mutable_numbers().data();
  if (f == U'+' && g == U'×' && a.is_numeric() && b.is_numeric() && la == lb) {
    matrix_product(ctx, a.numbers().data(), b.numbers().data(), out, m, n, p);
    for (std::size_t i = 0; i < m * p; ++i) check_finite(out[i]);
    return r;
  }
  const DyadicLoops& fl = dyadic_loops(f);
  std::vector<double> tmp(p);
  for (std::size_t i = 0; i < m; ++i) {
    ctx.charge(n * p);
    double* acc = out + i * p;
    for (std::size_t k = n; k-- > 0;) {
      const std::size_t ia = i * la + (la == 1 ? 0 : k), ib = (lb == 1 ? 0 : k) * p;
      if (k == n - 1) {
        dyadic_scalar_row(ctx, g, a, ia, b, ib, p, acc);
      } else {
        dyadic_scalar_row(ctx, g, a, ia, b, ib, p, tmp.data());
        fl.vv(ctx, tmp.data(), acc, acc, p);
      }
    }
  }
  return r;
}

}  // namespace igds::apl
