// Typed access to a value's elements, so that a structural function is written once for numbers
// and characters (a template on the element type).
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "interp/apl/context.h"
#include "interp/apl/value.h"

namespace igds::apl {

template <class T>
const T* elements(const Value& v) {
  if constexpr (std::is_same_v<T, double>) {
    return v.numbers().data();
  } else {
    return v.characters().data();
  }
}

template <class T>
T* mutable_elements(Value& v) {
  if constexpr (std::is_same_v<T, double>) {
    return v.mutable_numbers().data();
  } else {
    return v.mutable_characters().data();
  }
}

// The fill element of an array's kind (APL\360: 0 for numbers, blank for characters).
template <class T>
constexpr T fill_element() {
  if constexpr (std::is_same_v<T, double>) {
    return 0.0;
  } else {
    return U' ';
  }
}

// Calls f with a value of the element type of v (double or char32_t).
template <class F>
decltype(auto) by_kind(const Value& v, F&& f) {
  if (v.is_character()) return f(char32_t{});
  return f(double{});
}

// A new array of the kind of `like`.
template <class T>
Value new_array(Context& ctx, Shape shape) {
  if constexpr (std::is_same_v<T, double>) {
    return ctx.new_numbers(std::move(shape));
  } else {
    return ctx.new_characters(std::move(shape));
  }
}

// Strides of a row-major shape (elements between successive indices of each axis).
inline std::vector<std::size_t> strides_of(const Shape& shape) {
  std::vector<std::size_t> s(shape.size(), 1);
  for (std::size_t k = shape.size(); k-- > 1;) s[k - 1] = s[k] * shape[k];
  return s;
}

// The product of a range of axes (1 when empty).
inline std::size_t product(const Shape& shape, std::size_t from, std::size_t to) {
  std::size_t n = 1;
  for (std::size_t k = from; k < to; ++k) n *= shape[k];
  return n;
}

// The integers of an argument of rank 0 or 1 (RANK ERROR otherwise; an empty character
// vector is an empty list).
inline std::vector<std::int64_t> integer_list(const Value& a) {
  if (a.rank() > 1) rank_error();
  if (a.is_character()) {
    if (a.empty()) return {};
    domain_error();
  }
  std::vector<std::int64_t> out;
  out.reserve(a.size());
  for (double x : a.numbers()) out.push_back(integer_of(x));
  return out;
}

}  // namespace igds::apl
