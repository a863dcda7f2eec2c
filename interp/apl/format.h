// Numbers and arrays as APL shows them (APL2 Language Reference, "display of arrays"; the same
// rules as APL\360's output): high minus, ⎕PP significant digits, scaled form (1.5E¯7) for a
// number that needs more than ⎕PP digits or more than five leading zeros, matrix columns each
// in one format with their decimal points (or their E's) aligned.
#pragma once

#include <string>
#include <vector>

#include "interp/apl/context.h"
#include "interp/apl/value.h"

namespace igds::apl {

// One number with `pp` significant digits: 12, ¯3.5, 0.3333333333, 1.5E¯7, 1.23456789E10.
std::string format_number(double x, int pp);

// ⍕B: the characters of B's display (B itself when it is characters). A numeric array of rank
// r gives characters of rank r (a scalar gives a vector); its last axis is the display's width.
Value format(Context& ctx, const Value& b);

// A⍕B (APL2 "format by specification"): each column in a field of width W with P decimals
// (scaled form with -P significant digits when P is negative); W 0 takes the width needed plus
// one blank; a number too wide for its field fills it with *.
Value format_by_specification(Context& ctx, const Value& a, const Value& b);

// The lines that display a value: a vector on one line, a matrix as rows, higher ranks as
// matrices separated by one blank line per axis that moves on. UTF-8.
std::vector<std::string> display(Context& ctx, const Value& v);

}  // namespace igds::apl
