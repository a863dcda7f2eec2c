// An APL array: a ravel of doubles in row-major order and its shape (IGDS manual, section 7).
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "workspace/kernels/memory.h"

namespace igds {

// The numbers of an array.
using Ravel = std::vector<double, UnwrittenAllocator<double>>;

struct Array {
  std::vector<std::size_t> shape;
  Ravel ravel;

  Array() = default;
  // A zero-filled array of the given shape.
  explicit Array(std::vector<std::size_t> s) : shape(std::move(s)) {
    reserve_large(ravel, count(shape));
    ravel.resize(count(shape), 0.0);
  }
  // Copies are large arrays too (workspace/kernels/memory.h).
  Array(const Array& other) : shape(other.shape) { assign_large(ravel, other.ravel); }
  Array& operator=(const Array& other) {
    shape = other.shape;
    assign_large(ravel, other.ravel);  // a ravel assigned to itself is left as it is
    return *this;
  }
  Array(Array&&) = default;
  Array& operator=(Array&&) = default;

  static std::size_t count(const std::vector<std::size_t>& s) {
    std::size_t n = 1;
    for (auto d : s) n *= d;
    return s.empty() ? 0 : n;
  }
  std::size_t rank() const { return shape.size(); }
  std::size_t size() const { return ravel.size(); }
  bool empty() const { return ravel.empty(); }
  double* data() { return ravel.data(); }
  const double* data() const { return ravel.data(); }
  std::span<double> span() { return ravel; }
  std::span<const double> span() const { return ravel; }

  // The shape `s` for an output that overwrites every number (the numbers are unspecified): the
  // memory is kept when it holds them and is not more than twice what they need, so that a
  // grid made again at the same size is written into pages it already has.
  void reshape_for_output(std::vector<std::size_t> s) {
    const std::size_t n = count(s);
    // Freed first: two grids of the largest size at once may not fit.
    if (ravel.capacity() < n || ravel.capacity() / 2 > n) ravel = Ravel();
    shape = std::move(s);
    reserve_large(ravel, n);
    ravel.resize(n);
  }

  // A new array of shape `s` for an output that writes every number: none written before.
  static Array for_output(std::vector<std::size_t> s) {
    Array a;
    a.reshape_for_output(std::move(s));
    return a;
  }

  friend bool operator==(const Array&, const Array&) = default;
};

}  // namespace igds
