// The scalar functions (APL\360 User's Manual, chapter 2: + - × ÷ ⌈ ⌊ * ⍟ | ! ○ ? and the
// relations and logic): applied element by element with scalar extension, over whole ravels in
// tight loops (no per-element interpretation or allocation).
#pragma once

#include <cstddef>
#include <optional>

#include "interp/apl/context.h"
#include "interp/apl/value.h"

namespace igds::apl {

// f B; DOMAIN ERROR for characters or an argument outside the domain.
Value scalar_monadic(Context& ctx, char32_t glyph, Value b);

// A f B: equal shapes, or one argument a single element (scalar extension); RANK ERROR or
// LENGTH ERROR otherwise. Characters only with = and ≠ (a character never equals a number).
Value scalar_dyadic(Context& ctx, char32_t glyph, Value a, Value b);

// The loops of a dyadic scalar function over numbers, for the operators:
// vv: r[i] = a[i] f b[i]; sv: r[i] = a f b[i]; vs: r[i] = a[i] f b. r may be a or b.
struct DyadicLoops {
  void (*vv)(const Context&, const double* a, const double* b, double* r, std::size_t n);
  void (*sv)(const Context&, double a, const double* b, double* r, std::size_t n);
  void (*vs)(const Context&, const double* a, double b, double* r, std::size_t n);
  double (*one)(const Context&, double a, double b);
  bool associative;  // reduction and scan may then run left to right
};
const DyadicLoops& dyadic_loops(char32_t glyph);

// r[i] = a[ia] f b[ib + i] for i < n, any kinds of elements (characters with = and ≠ only).
void dyadic_scalar_row(const Context& ctx, char32_t glyph, const Value& a, std::size_t ia,
                       const Value& b, std::size_t ib, std::size_t n, double* r);

// The identity element of f, the reduction of an empty axis (APL\360 User's Manual, table of
// identity elements); nullopt where there is none (DOMAIN ERROR).
std::optional<double> identity_element(char32_t glyph);

// The shape of a scalar function's result; RANK ERROR or LENGTH ERROR when they do not agree.
Shape conforming_shape(const Value& a, const Value& b);

}  // namespace igds::apl
