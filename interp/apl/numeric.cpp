// ⊥ ⊤ ⌹: decode, encode, matrix inverse and matrix divide.
#include <algorithm>
#include <cmath>
#include <vector>

#include "interp/apl/elements.h"
#include "interp/apl/mixed.h"
#include "interp/apl/scalar.h"

namespace igds::apl {

namespace {

double residue(const Context& ctx, double a, double b) {
  return dyadic_loops(U'|').one(ctx, a, b);
}

void numbers_only(const Value& v) {
  if (v.is_character()) domain_error();
}

// A⌹B for B seen as m×n and A as m×p (row-major), by Householder QR: the least-squares
// solution n×p (APL\360 User's Manual, "matrix divide"; Golub and Van Loan, algorithm 5.3.2).
std::vector<double> least_squares(std::vector<double> r, std::size_t m, std::size_t n,
                                  std::vector<double> y, std::size_t p) {
  if (m < n) domain_error();
  double largest = 0;
  for (std::size_t j = 0; j < n; ++j) {
    double s = 0;
    for (std::size_t i = 0; i < m; ++i) s += r[i * n + j] * r[i * n + j];
    largest = std::max(largest, std::sqrt(s));
  }
  std::vector<double> v(m);
  for (std::size_t k = 0; k < n; ++k) {
    double norm = 0;
    for (std::size_t i = k; i < m; ++i) norm += r[i * n + k] * r[i * n + k];
    norm = std::sqrt(norm);
    // A column (nearly) dependent on the previous ones: B is singular (DOMAIN ERROR).
    if (!(norm > 1e-13 * largest)) domain_error();
    const double alpha = r[k * n + k] > 0 ? -norm : norm;
    double vv = 0;
    for (std::size_t i = k; i < m; ++i) {
      v[i] = r[i * n + k] - (i == k ? alpha : 0);
      vv += v[i] * v[i];
    }
    auto reflect = [&](std::vector<double>& x, std::size_t cols, std::size_t from) {
      for (std::size_t j = from; j < cols; ++j) {
        double s = 0;
        for (std::size_t i = k; i < m; ++i) s += v[i] * x[i * cols + j];
        s = 2 * s / vv;
        for (std::size_t i = k; i < m; ++i) x[i * cols + j] -= s * v[i];
      }
    };
    if (vv > 0) {
      reflect(r, n, k);
      reflect(y, p, 0);
    }
    if (!(std::fabs(r[k * n + k]) > 1e-13 * largest)) domain_error();
  }
  std::vector<double> x(n * p);
  for (std::size_t j = 0; j < p; ++j) {
    for (std::size_t k = n; k-- > 0;) {
      double s = y[k * p + j];
      for (std::size_t l = k + 1; l < n; ++l) s -= r[k * n + l] * x[l * p + j];
      x[k * p + j] = s / r[k * n + k];
    }
  }
  for (double e : x)
    if (!std::isfinite(e)) domain_error();
  return x;
}

// Rows and columns of an argument of ⌹ (a vector is one column, a scalar 1×1).
std::pair<std::size_t, std::size_t> matrix_shape(const Value& v) {
  if (v.rank() > 2) rank_error();
  if (v.rank() == 0) return {1, 1};
  if (v.rank() == 1) return {v.shape()[0], 1};
  return {v.shape()[0], v.shape()[1]};
}

}  // namespace

Value decode(Context& ctx, const Value& a, const Value& b) {
  // A⊥B (APL\360 User's Manual, "decode"): the value of the digits B in the number system of
  // radices A, for each vector along A's last axis and B's first; a length of 1 is extended.
  numbers_only(a);
  numbers_only(b);
  const std::size_t na = a.rank() == 0 ? 1 : a.shape().back();
  const std::size_t nb = b.rank() == 0 ? 1 : b.shape().front();
  if (na != nb && na != 1 && nb != 1) length_error();
  const std::size_t n = (na == 0 || nb == 0) ? 0 : std::max(na, nb);
  Shape shape;
  if (a.rank() > 0) shape.assign(a.shape().begin(), a.shape().end() - 1);
  const std::size_t rows = element_count(shape);
  if (b.rank() > 0) shape.insert(shape.end(), b.shape().begin() + 1, b.shape().end());
  const std::size_t cols = b.rank() > 0 ? product(b.shape(), 1, b.rank()) : 1;
  Value r = ctx.new_numbers(shape);
  ctx.charge(r.size() * n);
  auto x = a.numbers(), y = b.numbers();
  auto out = r.mutable_numbers();
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) {
      double v = 0;  // Horner's rule over the digits
      for (std::size_t k = 0; k < n; ++k)
        v = v * x[i * na + (na == 1 ? 0 : k)] + y[(nb == 1 ? 0 : k) * cols + j];
      if (!std::isfinite(v)) domain_error();
      out[i * cols + j] = v;
    }
  }
  return r;
}

Value encode(Context& ctx, const Value& a, const Value& b) {
  // A⊤B (APL\360 User's Manual, "encode"): the digits of B in the number system of radices A,
  // one vector along A's first axis per representation; a radix of 0 takes what remains.
  numbers_only(a);
  numbers_only(b);
  const std::size_t na = a.rank() == 0 ? 1 : a.shape().front();
  const std::size_t ca = na == 0 ? 0 : a.size() / na;
  const std::size_t pb = b.size();
  Shape shape = a.shape();
  shape.insert(shape.end(), b.shape().begin(), b.shape().end());
  Value r = ctx.new_numbers(shape);
  if (r.empty()) return r;
  auto x = a.numbers(), y = b.numbers();
  auto out = r.mutable_numbers();
  for (std::size_t c = 0; c < ca; ++c) {
    for (std::size_t j = 0; j < pb; ++j) {
      double v = y[j];
      for (std::size_t k = na; k-- > 0;) {
        const double radix = x[k * ca + c];
        double digit;
        if (radix == 0) {
          digit = v;
          v = 0;
        } else {
          digit = residue(ctx, radix, v);
          v = (v - digit) / radix;
          if (near_integer(v, ctx.ct)) v = std::round(v);
        }
        out[(k * ca + c) * pb + j] = digit;
      }
    }
  }
  return r;
}

Value matrix_divide(Context& ctx, const Value& a, const Value& b) {
  numbers_only(a);
  numbers_only(b);
  auto [m, n] = matrix_shape(b);
  auto [ma, p] = matrix_shape(a);
  if (ma != m) length_error();
  ctx.charge(m * n * (n + p) + 1);
  auto x = least_squares(std::vector<double>(b.numbers().begin(), b.numbers().end()), m, n,
                         std::vector<double>(a.numbers().begin(), a.numbers().end()), p);
  Shape shape;
  if (b.rank() == 2) shape.push_back(n);
  if (a.rank() == 2) shape.push_back(p);
  return Value::of_numbers(std::move(shape), std::span<const double>(x));
}

Value matrix_inverse(Context& ctx, const Value& b) {
  // ⌹B is (the identity of B's rows)⌹B; ⌹ of a scalar is its reciprocal.
  numbers_only(b);
  const std::size_t m = matrix_shape(b).first;
  if (b.rank() == 0) return matrix_divide(ctx, Value::number(1), b);
  Value identity = Value::zeros({m, m});
  auto id = identity.mutable_numbers();
  for (std::size_t i = 0; i < m; ++i) id[i * m + i] = 1;
  return matrix_divide(ctx, identity, b);
}

}  // namespace igds::apl
