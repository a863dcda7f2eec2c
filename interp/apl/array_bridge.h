// APL values and igds's workspace arrays (workspace/kernels/array.h): the same ravel of doubles
// and shape. igds keeps an empty variable as an Array with no shape and no elements (shape 0 in
// APL, section "END APL" of docs/interp.md), and a scalar as no shape and one element.
#pragma once

#include <span>

#include "interp/apl/error.h"
#include "interp/apl/value.h"
#include "workspace/kernels/array.h"

namespace igds::apl {

inline Value to_value(const igds::Array& a) {
  if (a.shape.empty()) {
    if (a.ravel.empty()) return Value();
    return Value::number(a.ravel[0]);
  }
  return Value::of_numbers(a.shape, std::span<const double>(a.ravel));
}

// DOMAIN ERROR for characters: the workspace holds numbers only.
inline igds::Array to_array(const Value& v) {
  if (v.is_character()) throw Error(ErrorKind::domain);
  igds::Array a;
  a.shape = v.shape();
  auto x = v.numbers();
  a.ravel.assign(x.begin(), x.end());
  return a;
}

}  // namespace igds::apl
