#include "interp/apl/scalar.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define IGDS_X86 1
#else
#define IGDS_X86 0
#endif

namespace igds::apl {

namespace {

constexpr std::size_t chunk = 2048;

// Results must stay finite: APL has no infinity, overflow is a DOMAIN ERROR. Two numbers at a
// time on x86-64 (!(|r| <= DBL_MAX) is also true of a NaN), so that the check costs little
// beside the loop it checks.
void check_finite(const double* r, std::size_t n) {
  std::size_t i = 0;
  bool bad = false;
#if IGDS_X86
  const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7FFFFFFFFFFFFFFF));
  const __m128d largest = _mm_set1_pd(DBL_MAX);
  __m128d out = _mm_setzero_pd();
  for (; i + 2 <= n; i += 2)
    out = _mm_or_pd(out, _mm_cmpnle_pd(_mm_and_pd(_mm_loadu_pd(r + i), magnitude), largest));
  bad = _mm_movemask_pd(out) != 0;
#endif
  for (; i < n; ++i) bad |= !(std::fabs(r[i]) <= DBL_MAX);
  if (bad) domain_error();
}

// --- dyadic element functions ---------------------------------------------------------------

struct Plus {
  static constexpr bool may_overflow = true, associative = true;
  static double f(const Context&, double a, double b) { return a + b; }
};
struct Minus {
  static constexpr bool may_overflow = true, associative = false;
  static double f(const Context&, double a, double b) { return a - b; }
};
struct Times {
  static constexpr bool may_overflow = true, associative = true;
  static double f(const Context&, double a, double b) { return a * b; }
};
struct Divide {
  static constexpr bool may_overflow = true, associative = false;
  // 0÷0 is 1 (APL\360 User's Manual, "divide").
  static double f(const Context&, double a, double b) {
    if (b == 0) {
      if (a == 0) return 1;
      domain_error();
    }
    return a / b;
  }
};
struct Maximum {
  static constexpr bool may_overflow = false, associative = true;
  static double f(const Context&, double a, double b) { return a > b ? a : b; }
};
struct Minimum {
  static constexpr bool may_overflow = false, associative = true;
  static double f(const Context&, double a, double b) { return a < b ? a : b; }
};
struct Power {
  static constexpr bool may_overflow = true, associative = false;
  static double f(const Context&, double a, double b) {
    if (a == 0) {
      if (b < 0) domain_error();
      return b == 0 ? 1 : 0;
    }
    if (a < 0 && b != std::floor(b)) domain_error();  // no complex results in APL\360
    return std::pow(a, b);
  }
};
struct Logarithm {
  static constexpr bool may_overflow = true, associative = false;
  static double f(const Context&, double a, double b) {
    if (a <= 0 || b <= 0) domain_error();
    if (a == 1) {
      if (b == 1) return 1;
      domain_error();
    }
    return std::log(b) / std::log(a);
  }
};
struct Residue {
  static constexpr bool may_overflow = false, associative = false;
  // A|B (APL2 Language Reference, "residue"): B when A is 0; 0 when B÷A is tolerantly an
  // integer; otherwise B-A×⌊B÷A, with the sign of A.
  static double f(const Context& c, double a, double b) {
    if (a == 0) return b;
    double q = b / a;
    if (std::isfinite(q) && tolerant_equal(q, std::round(q), c.ct)) return 0;
    double r = std::fmod(b, a);
    if (r != 0 && ((r < 0) != (a < 0))) r += a;
    return r;
  }
};

// C(n, k) for integers 0 ≤ k ≤ n, by the product (exact while it fits), else by lgamma.
double choose(double n, double k) {
  k = std::min(k, n - k);
  if (k < 0) return 0;
  if (k > 1000)
    return std::round(std::exp(std::lgamma(n + 1) - std::lgamma(k + 1) - std::lgamma(n - k + 1)));
  double r = 1;
  for (double i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return std::round(r);
}

struct Binomial {
  static constexpr bool may_overflow = true, associative = false;
  // A!B = (!B)÷(!A)×!B-A, extended to negative integers by its limits (APL2 Language
  // Reference, "binomial", the table of cases by the signs of A, B and B-A).
  static double f(const Context&, double a, double b) {
    if (near_integer(a) && near_integer(b)) {
      double A = std::round(a), B = std::round(b);
      if (A >= 0 && B >= 0) return B >= A ? choose(B, A) : 0;
      if (A >= 0 && B < 0) return (std::fmod(A, 2) == 0 ? 1 : -1) * choose(A - B - 1, A);
      if (A < 0 && B >= 0) return 0;
      if (B < A) return 0;
      return (std::fmod(B - A, 2) == 0 ? 1 : -1) * choose(-A - 1, B - A);
    }
    auto pole = [](double x) { return x <= 0 && near_integer(x); };
    if (pole(b + 1)) domain_error();
    if (pole(a + 1) || pole(b - a + 1)) return 0;
    return std::tgamma(b + 1) / (std::tgamma(a + 1) * std::tgamma(b - a + 1));
  }
};
struct Circle {
  static constexpr bool may_overflow = true, associative = false;
  // A○B (APL\360 User's Manual, "circular functions"); NaN results are caught as DOMAIN ERROR.
  static double f(const Context&, double a, double b) {
    if (!near_integer(a) || std::fabs(a) > 7.5) domain_error();
    switch (std::llround(a)) {
      case 0:
        return std::sqrt(1 - b * b);
      case 1:
        return std::sin(b);
      case 2:
        return std::cos(b);
      case 3:
        return std::tan(b);
      case 4:
        return std::sqrt(1 + b * b);
      case 5:
        return std::sinh(b);
      case 6:
        return std::cosh(b);
      case 7:
        return std::tanh(b);
      case -1:
        return std::asin(b);
      case -2:
        return std::acos(b);
      case -3:
        return std::atan(b);
      case -4:
        return std::sqrt(b * b - 1);
      case -5:
        return std::asinh(b);
      case -6:
        return std::acosh(b);
      case -7:
        return std::atanh(b);
      default:
        domain_error();
    }
  }
};
struct Less {
  static constexpr bool may_overflow = false, associative = false;
  static double f(const Context& c, double a, double b) {
    return a < b && !tolerant_equal(a, b, c.ct);
  }
};
struct LessEqual {
  static constexpr bool may_overflow = false, associative = false;
  static double f(const Context& c, double a, double b) {
    return a <= b || tolerant_equal(a, b, c.ct);
  }
};
struct Equal {
  static constexpr bool may_overflow = false, associative = false;
  static double f(const Context& c, double a, double b) { return tolerant_equal(a, b, c.ct); }
};
struct GreaterEqual {
  static constexpr bool may_overflow = false, associative = false;
  static double f(const Context& c, double a, double b) {
    return a >= b || tolerant_equal(a, b, c.ct);
  }
};
struct Greater {
  static constexpr bool may_overflow = false, associative = false;
  static double f(const Context& c, double a, double b) {
    return a > b && !tolerant_equal(a, b, c.ct);
  }
};
struct NotEqual {
  static constexpr bool may_overflow = false, associative = false;
  static double f(const Context& c, double a, double b) { return !tolerant_equal(a, b, c.ct); }
};
struct And {
  static constexpr bool may_overflow = false, associative = true;
  static double f(const Context&, double a, double b) {
    const bool x = boolean_of(a), y = boolean_of(b);  // both checked, whatever the first
    return x && y;
  }
};
struct Or {
  static constexpr bool may_overflow = false, associative = true;
  static double f(const Context&, double a, double b) {
    const bool x = boolean_of(a), y = boolean_of(b);
    return x || y;
  }
};
struct Nand {
  static constexpr bool may_overflow = false, associative = false;
  static double f(const Context&, double a, double b) {
    const bool x = boolean_of(a), y = boolean_of(b);
    return !(x && y);
  }
};
struct Nor {
  static constexpr bool may_overflow = false, associative = false;
  static double f(const Context&, double a, double b) {
    const bool x = boolean_of(a), y = boolean_of(b);
    return !(x || y);
  }
};

template <class Op>
void loop_vv(const Context& c, const double* a, const double* b, double* r, std::size_t n) {
  for (std::size_t s = 0; s < n; s += chunk) {
    const std::size_t e = std::min(n, s + chunk);
    for (std::size_t i = s; i < e; ++i) r[i] = Op::f(c, a[i], b[i]);
    if constexpr (Op::may_overflow) check_finite(r + s, e - s);
  }
}

template <class Op>
void loop_sv(const Context& c, double a, const double* b, double* r, std::size_t n) {
  for (std::size_t s = 0; s < n; s += chunk) {
    const std::size_t e = std::min(n, s + chunk);
    for (std::size_t i = s; i < e; ++i) r[i] = Op::f(c, a, b[i]);
    if constexpr (Op::may_overflow) check_finite(r + s, e - s);
  }
}

template <class Op>
void loop_vs(const Context& c, const double* a, double b, double* r, std::size_t n) {
  for (std::size_t s = 0; s < n; s += chunk) {
    const std::size_t e = std::min(n, s + chunk);
    for (std::size_t i = s; i < e; ++i) r[i] = Op::f(c, a[i], b);
    if constexpr (Op::may_overflow) check_finite(r + s, e - s);
  }
}

template <class Op>
double one(const Context& c, double a, double b) {
  double r = Op::f(c, a, b);
  if constexpr (Op::may_overflow) check_finite(&r, 1);
  return r;
}

template <class Op>
constexpr DyadicLoops loops_of() {
  return {loop_vv<Op>, loop_sv<Op>, loop_vs<Op>, one<Op>, Op::associative};
}

// --- monadic element functions --------------------------------------------------------------

double factorial(double b) {
  if (b < 0 && near_integer(b)) domain_error();
  if (near_integer(b) && b <= 170) {
    double r = 1;
    for (double i = 2; i <= std::round(b); ++i) r *= i;
    return r;
  }
  return std::tgamma(b + 1);  // !B is Γ(B+1) (APL\360 User's Manual, "factorial")
}

double reciprocal(double b) {
  if (b == 0) domain_error();
  return 1 / b;
}

double natural_logarithm(double b) {
  if (b <= 0) domain_error();
  return std::log(b);
}

template <class F>
void map(bool may_overflow, double* r, const double* b, std::size_t n, F f) {
  for (std::size_t s = 0; s < n; s += chunk) {
    const std::size_t e = std::min(n, s + chunk);
    for (std::size_t i = s; i < e; ++i) r[i] = f(b[i]);
    if (may_overflow) check_finite(r + s, e - s);
  }
}

}  // namespace

const DyadicLoops& dyadic_loops(char32_t glyph) {
  static constexpr DyadicLoops plus = loops_of<Plus>(), minus = loops_of<Minus>(),
                               times = loops_of<Times>(), divide = loops_of<Divide>(),
                               maximum = loops_of<Maximum>(), minimum = loops_of<Minimum>(),
                               power = loops_of<Power>(), logarithm = loops_of<Logarithm>(),
                               residue = loops_of<Residue>(), binomial = loops_of<Binomial>(),
                               circle = loops_of<Circle>(), less = loops_of<Less>(),
                               less_equal = loops_of<LessEqual>(), equal = loops_of<Equal>(),
                               greater_equal = loops_of<GreaterEqual>(),
                               greater = loops_of<Greater>(), not_equal = loops_of<NotEqual>(),
                               and_ = loops_of<And>(), or_ = loops_of<Or>(),
                               nand = loops_of<Nand>(), nor = loops_of<Nor>();
  switch (glyph) {
    case U'+':
      return plus;
    case U'-':
      return minus;
    case U'×':
      return times;
    case U'÷':
      return divide;
    case U'⌈':
      return maximum;
    case U'⌊':
      return minimum;
    case U'*':
      return power;
    case U'⍟':
      return logarithm;
    case U'|':
      return residue;
    case U'!':
      return binomial;
    case U'○':
      return circle;
    case U'<':
      return less;
    case U'≤':
      return less_equal;
    case U'=':
      return equal;
    case U'≥':
      return greater_equal;
    case U'>':
      return greater;
    case U'≠':
      return not_equal;
    case U'∧':
      return and_;
    case U'∨':
      return or_;
    case U'⍲':
      return nand;
    case U'⍱':
      return nor;
    default:
      syntax_error();
  }
}

std::optional<double> identity_element(char32_t glyph) {
  switch (glyph) {
    case U'+':
    case U'-':
    case U'|':
    case U'<':
    case U'>':
    case U'≠':
    case U'∨':
      return 0.0;
    case U'×':
    case U'÷':
    case U'*':
    case U'!':
    case U'≤':
    case U'=':
    case U'≥':
    case U'∧':
      return 1.0;
    case U'⌊':
      return DBL_MAX;
    case U'⌈':
      return -DBL_MAX;
    default:
      return std::nullopt;
  }
}

Shape conforming_shape(const Value& a, const Value& b) {
  if (a.shape() == b.shape()) return a.shape();
  const bool a_one = a.size() == 1, b_one = b.size() == 1;
  if (a_one && b_one) return a.rank() >= b.rank() ? a.shape() : b.shape();
  if (a_one) return b.shape();
  if (b_one) return a.shape();
  if (a.rank() != b.rank()) rank_error();
  length_error();
}

Value scalar_monadic(Context& ctx, char32_t glyph, Value b) {
  if (b.is_character()) domain_error();
  const std::size_t n = b.size();
  // A temporary argument receives the result in place.
  const bool in_place = b.unique();
  Value r = in_place ? std::move(b) : ctx.new_numbers(b.shape());
  if (in_place) ctx.charge(n);
  double* y = r.mutable_numbers().data();
  const double* x = in_place ? y : b.numbers().data();
  const double ct = ctx.ct;
  switch (glyph) {
    case U'+':
      map(false, y, x, n, [](double v) { return v; });
      break;
    case U'-':
      map(false, y, x, n, [](double v) { return -v; });
      break;
    case U'×':
      map(false, y, x, n, [](double v) { return double((v > 0) - (v < 0)); });
      break;
    case U'÷':
      map(true, y, x, n, reciprocal);
      break;
    case U'⌈':
      map(false, y, x, n, [ct](double v) { return -tolerant_floor(-v, ct); });
      break;
    case U'⌊':
      map(false, y, x, n, [ct](double v) { return tolerant_floor(v, ct); });
      break;
    case U'*':
      map(true, y, x, n, [](double v) { return std::exp(v); });
      break;
    case U'⍟':
      map(true, y, x, n, natural_logarithm);
      break;
    case U'|':
      map(false, y, x, n, [](double v) { return std::fabs(v); });
      break;
    case U'!':
      map(true, y, x, n, factorial);
      break;
    case U'○':
      map(true, y, x, n, [](double v) { return std::numbers::pi * v; });
      break;
    case U'~':
      map(false, y, x, n, [](double v) { return double(!boolean_of(v)); });
      break;
    case U'?':
      // Roll (APL\360 User's Manual, "roll"): an integer from ⎕IO to B-1+⎕IO, at random.
      for (std::size_t i = 0; i < n; ++i) {
        double m = static_cast<double>(count_of(x[i]));
        if (m < 1) domain_error();
        y[i] = ctx.io + std::floor(m * ctx.random());
      }
      break;
    default:
      syntax_error();
  }
  return r;
}

void dyadic_scalar_row(const Context& ctx, char32_t glyph, const Value& a, std::size_t ia,
                       const Value& b, std::size_t ib, std::size_t n, double* r) {
  if (a.is_numeric() && b.is_numeric()) {
    dyadic_loops(glyph).sv(ctx, a.numbers()[ia], b.numbers().data() + ib, r, n);
    return;
  }
  if (glyph != U'=' && glyph != U'≠') domain_error();
  const double differ = glyph == U'≠';
  if (a.is_character() != b.is_character()) {
    std::fill(r, r + n, differ);
    return;
  }
  const char32_t c = a.characters()[ia];
  const char32_t* y = b.characters().data() + ib;
  for (std::size_t i = 0; i < n; ++i) r[i] = (c != y[i]) == (differ != 0);
}

Value scalar_dyadic(Context& ctx, char32_t glyph, Value a, Value b) {
  Shape shape = conforming_shape(a, b);
  const std::size_t n = element_count(shape);
  const bool a_scalar = a.size() == 1 && n != 1, b_scalar = b.size() == 1 && n != 1;
  if (a.is_character() || b.is_character()) {
    if (glyph != U'=' && glyph != U'≠') domain_error();
    Value r = ctx.new_numbers(std::move(shape));
    double* y = r.mutable_numbers().data();
    const double differ = glyph == U'≠';
    if (a.is_character() != b.is_character()) {
      std::fill(y, y + n, differ);
      return r;
    }
    auto x = a.characters(), z = b.characters();
    for (std::size_t i = 0; i < n; ++i) {
      char32_t l = x[a_scalar ? 0 : i], m = z[b_scalar ? 0 : i];
      y[i] = (l != m) == (differ != 0);
    }
    return r;
  }
  const DyadicLoops& loops = dyadic_loops(glyph);
  // A temporary argument of the result's shape receives the result in place.
  Value r;
  const double *x = nullptr, *z = nullptr;
  double* y = nullptr;
  if (!b_scalar && b.unique() && b.shape() == shape) {
    ctx.charge(n);
    r = std::move(b);
    y = r.mutable_numbers().data();
    x = a.numbers().data();
    z = y;
  } else if (!a_scalar && a.unique() && a.shape() == shape) {
    ctx.charge(n);
    r = std::move(a);
    y = r.mutable_numbers().data();
    x = y;
    z = b.numbers().data();
  } else {
    r = ctx.new_numbers(std::move(shape));
    y = r.mutable_numbers().data();
    x = a.numbers().data();
    z = b.numbers().data();
  }
  if (a_scalar) {
    loops.sv(ctx, x[0], z, y, n);
  } else if (b_scalar) {
    loops.vs(ctx, x, z[0], y, n);
  } else {
    loops.vv(ctx, x, z, y, n);
  }
  return r;
}

}  // namespace igds::apl
