// An APL\360 array: a shape and a ravel of numbers or of characters, never both (flat arrays,
// no nesting). The ravel is shared between copies and copied only when one of them is changed,
// so that passing a workspace-sized array around (INTPN is 12 M doubles) costs nothing.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace igds::apl {

using Shape = std::vector<std::size_t>;

// Elements of a shape multiplied (1 for a scalar).
std::size_t element_count(const Shape& shape);

// An allocator that leaves new elements uninitialised: a result is written once, not twice.
template <class T>
struct UninitialisedAllocator {
  using value_type = T;
  UninitialisedAllocator() = default;
  template <class U>
  UninitialisedAllocator(const UninitialisedAllocator<U>&) {}
  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(::operator new(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) { ::operator delete(p, n * sizeof(T)); }
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const UninitialisedAllocator<U>&) const {
    return true;
  }
};

using Numbers = std::vector<double, UninitialisedAllocator<double>>;
using Characters = std::vector<char32_t, UninitialisedAllocator<char32_t>>;

class Value {
 public:
  // The empty numeric vector (⍳0); it allocates nothing.
  Value();

  static Value number(double x);
  static Value character(char32_t c);
  // A numeric vector.
  static Value vector(std::initializer_list<double> xs);
  static Value vector(std::span<const double> xs);
  // A character vector of the UTF-8 text.
  static Value text(std::string_view utf8);
  static Value text(std::u32string_view chars);
  static Value of_numbers(Shape shape, Numbers ravel);
  static Value of_numbers(Shape shape, std::span<const double> ravel);
  static Value of_characters(Shape shape, Characters ravel);
  // Arrays of the shape whose elements are to be written by the caller.
  static Value uninitialised_numbers(Shape shape);
  static Value uninitialised_characters(Shape shape);
  // Arrays of the shape filled with zeros or blanks.
  static Value zeros(Shape shape);
  static Value blanks(Shape shape);

  const Shape& shape() const { return shape_; }
  std::size_t rank() const { return shape_.size(); }
  std::size_t size() const;
  bool empty() const { return size() == 0; }
  bool is_character() const { return characters_ != nullptr; }
  bool is_numeric() const { return numbers_ != nullptr; }

  std::span<const double> numbers() const;
  std::span<const char32_t> characters() const;
  // Writable ravels: the storage is first copied when another value shares it.
  std::span<double> mutable_numbers();
  std::span<char32_t> mutable_characters();
  // True when no other value shares the storage (it may then be written in place).
  bool unique() const;

  // The same ravel under another shape of the same element count (no copy).
  Value reshaped(Shape shape) const;
  // The characters as UTF-8 (the ravel in order).
  std::string utf8() const;

  // Same shape, same kind, same elements (exactly).
  friend bool operator==(const Value& a, const Value& b);

 private:
  Value(Shape shape, std::shared_ptr<Numbers> numbers, std::shared_ptr<Characters> characters)
      : shape_(std::move(shape)),
        numbers_(std::move(numbers)),
        characters_(std::move(characters)) {}

  Shape shape_;
  std::shared_ptr<Numbers> numbers_;
  std::shared_ptr<Characters> characters_;
};

}  // namespace igds::apl
