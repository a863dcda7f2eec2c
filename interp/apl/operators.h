// The operators of APL\360 (User's Manual, chapter 4): reduction f/ f⌿, scan f\ f⍀, outer
// product ∘.f and inner product f.g, for the scalar dyadic functions f and g. Reduction is
// defined from the right: f/1 2 3 is 1 f (2 f 3).
#pragma once

#include "interp/apl/context.h"
#include "interp/apl/value.h"

namespace igds::apl {

Value reduce(Context& ctx, char32_t f, const Value& b, const Value* axis, bool first_axis);
Value scan(Context& ctx, char32_t f, const Value& b, const Value* axis, bool first_axis);
Value outer_product(Context& ctx, char32_t f, const Value& a, const Value& b);
Value inner_product(Context& ctx, char32_t f, char32_t g, const Value& a, const Value& b);

}  // namespace igds::apl
