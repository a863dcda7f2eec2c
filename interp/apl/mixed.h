// The mixed functions (APL\360 User's Manual, chapter 3; APL2 Language Reference for the
// details it leaves open): structure, selection, search, ordering and the numeric ones.
// `axis` is the value in brackets after the function, or null.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "interp/apl/context.h"
#include "interp/apl/value.h"

namespace igds::apl {

// The axis named by [k] (⎕IO-based) among `rank` axes, or `otherwise` when none is given.
// DOMAIN ERROR for a non-integer, INDEX ERROR for an axis the array does not have.
std::size_t axis_of(const Context& ctx, const Value* axis, std::size_t rank, std::size_t otherwise);

// --- structure (structural.cpp) ---
Value shape_of(Context& ctx, const Value& b);                                     // ⍴B
Value reshape(Context& ctx, const Value& a, const Value& b);                      // A⍴B
Value ravel(Context& ctx, const Value& b, const Value* axis);                     // ,B  ,[k]B
Value catenate(Context& ctx, const Value& a, const Value& b, const Value* axis);  // A,B A,[k]B
Value reverse(Context& ctx, const Value& b, const Value* axis, bool first_axis);  // ⌽B ⊖B
Value rotate(Context& ctx, const Value& a, const Value& b, const Value* axis,
             bool first_axis);                                  // A⌽B A⊖B
Value transpose(Context& ctx, const Value& b);                  // ⍉B
Value transpose(Context& ctx, const Value& a, const Value& b);  // A⍉B

// --- selection (select.cpp) ---
Value take(Context& ctx, const Value& a, const Value& b, const Value* axis);  // A↑B
Value drop(Context& ctx, const Value& a, const Value& b, const Value* axis);  // A↓B
Value replicate(Context& ctx, const Value& a, const Value& b, const Value* axis,
                bool first_axis);  // A/B A⌿B
Value expand(Context& ctx, const Value& a, const Value& b, const Value* axis,
             bool first_axis);  // A\B A⍀B
// B[I;J;...]: one entry per axis, an elided index is nullopt.
Value index(Context& ctx, const Value& b, const std::vector<std::optional<Value>>& indices);
// B[I;J;...]←C, in place (B's ravel is copied first if it is shared). B is unchanged when the
// assignment fails: every check comes before the first element is written.
void index_assign(Context& ctx, Value& b, const std::vector<std::optional<Value>>& indices,
                  const Value& c);

// --- search and order (search.cpp) ---
Value iota(Context& ctx, const Value& b);                            // ⍳B
Value index_of(Context& ctx, const Value& a, const Value& b);        // A⍳B
Value member_of(Context& ctx, const Value& a, const Value& b);       // A∊B
Value without(Context& ctx, const Value& a, const Value& b);         // A~B
Value grade(Context& ctx, const Value& b, bool up);                  // ⍋B ⍒B
Value grade(Context& ctx, const Value& a, const Value& b, bool up);  // A⍋B A⍒B (collating)
Value deal(Context& ctx, const Value& a, const Value& b);            // A?B

// --- numeric (numeric.cpp) ---
Value decode(Context& ctx, const Value& a, const Value& b);         // A⊥B
Value encode(Context& ctx, const Value& a, const Value& b);         // A⊤B
Value matrix_inverse(Context& ctx, const Value& b);                 // ⌹B
Value matrix_divide(Context& ctx, const Value& a, const Value& b);  // A⌹B

}  // namespace igds::apl
