// An APL\360 array: a shape and a ravel of numbers or of characters, never both (flat arrays,
// no nesting). The ravel is shared between copies and copied only when one of them is changed,
// so that passing a workspace-sized array around (INTPN is 12 M doubles) costs nothing; an array
// of one element (a scalar, a loop's counter) holds it in the value itself, so that making,
// copying and dropping it allocates nothing.
#pragma once

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "workspace/kernels/memory.h"

namespace igds::apl {

// The lengths of an array's axes. Most arrays have at most three axes: those lengths are held in
// the shape itself, so that making and copying a value allocates nothing for its shape.
class Shape {
 public:
  using value_type = std::size_t;
  using size_type = std::size_t;
  using iterator = std::size_t*;
  using const_iterator = const std::size_t*;

  Shape() = default;
  Shape(std::initializer_list<std::size_t> lengths) : Shape(lengths.begin(), lengths.end()) {}
  explicit Shape(std::size_t count, std::size_t length = 0) { resize(count, length); }
  template <class It>
  Shape(It first, It last) {
    assign(first, last);
  }
  Shape(const std::vector<std::size_t>& lengths) : Shape(lengths.begin(), lengths.end()) {}
  Shape(const Shape& other) { copy(other); }
  Shape(Shape&& other) noexcept { take(other); }
  Shape& operator=(const Shape& other) {
    if (this != &other) copy(other);
    return *this;
  }
  Shape& operator=(Shape&& other) noexcept {
    if (this != &other) take(other);
    return *this;
  }
  ~Shape() = default;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t* data() { return big_ ? big_.get() : small_; }
  const std::size_t* data() const { return big_ ? big_.get() : small_; }
  iterator begin() { return data(); }
  iterator end() { return data() + size_; }
  const_iterator begin() const { return data(); }
  const_iterator end() const { return data() + size_; }
  std::size_t& operator[](std::size_t i) { return data()[i]; }
  std::size_t operator[](std::size_t i) const { return data()[i]; }
  std::reverse_iterator<const_iterator> rbegin() const {
    return std::reverse_iterator<const_iterator>(end());
  }
  std::reverse_iterator<const_iterator> rend() const {
    return std::reverse_iterator<const_iterator>(begin());
  }
  std::size_t& at(std::size_t i) { return data()[i]; }
  std::size_t& front() { return data()[0]; }
  std::size_t front() const { return data()[0]; }
  std::size_t& back() { return data()[size_ - 1]; }
  std::size_t back() const { return data()[size_ - 1]; }

  void clear() { size_ = 0; }
  void reserve(std::size_t n);
  void resize(std::size_t n, std::size_t length = 0);
  void push_back(std::size_t length);
  void pop_back() { --size_; }
  template <class It>
  void assign(It first, It last) {
    const auto n = static_cast<std::size_t>(std::distance(first, last));
    std::size_t copy[small];  // `first` may be this shape's own
    if (n <= small) {
      std::copy(first, last, copy);
      size_ = 0;
      reserve(n);
      std::copy(copy, copy + n, data());
    } else {
      std::vector<std::size_t> lengths(first, last);
      size_ = 0;
      reserve(n);
      std::copy(lengths.begin(), lengths.end(), data());
    }
    size_ = n;
  }
  void assign(std::size_t n, std::size_t length) {
    size_ = 0;
    resize(n, length);
  }
  iterator insert(const_iterator at, std::size_t length);
  template <class It>
  iterator insert(const_iterator at, It first, It last) {
    const std::size_t k = static_cast<std::size_t>(at - begin());
    const std::vector<std::size_t> lengths(first, last);  // `first` may be this shape's own
    Shape rest(begin() + k, end());
    resize(k);
    for (std::size_t x : lengths) push_back(x);
    for (std::size_t x : rest) push_back(x);
    return begin() + k;
  }
  iterator erase(const_iterator at) { return erase(at, at + 1); }
  iterator erase(const_iterator first, const_iterator last);

  friend bool operator==(const Shape& a, const Shape& b) {
    return a.size_ == b.size_ && std::equal(a.begin(), a.end(), b.begin());
  }
  operator std::vector<std::size_t>() const { return {begin(), end()}; }

 private:
  static constexpr std::size_t small = 3;
  void copy(const Shape& other) {
    if (other.big_) {
      assign(other.begin(), other.end());
      return;
    }
    big_.reset();
    capacity_ = small;
    size_ = other.size_;
    small_[0] = other.small_[0];
    small_[1] = other.small_[1];
    small_[2] = other.small_[2];
  }
  void take(Shape& other) {
    size_ = other.size_;
    big_ = std::move(other.big_);
    capacity_ = big_ ? other.capacity_ : static_cast<std::uint32_t>(small);
    small_[0] = other.small_[0];
    small_[1] = other.small_[1];
    small_[2] = other.small_[2];
    other.size_ = 0;
    other.capacity_ = small;
  }

  std::size_t small_[small] = {};
  std::unique_ptr<std::size_t[]> big_;  // when more than `small` lengths
  std::uint32_t size_ = 0, capacity_ = small;
};

// Elements of a shape multiplied (1 for a scalar).
std::size_t element_count(const Shape& shape);

// A result's elements are written once, by what makes them (workspace/kernels/memory.h).
using Numbers = std::vector<double, UnwrittenAllocator<double>>;
using Characters = std::vector<char32_t, UnwrittenAllocator<char32_t>>;

class Value {
 public:
  // The empty numeric vector (⍳0); it allocates nothing.
  Value();

  static Value number(double x) { return Value(x); }
  // A number (a scalar), made where it is to be (stack.emplace_back(x)).
  explicit Value(double x) : one_(true) { one_number_ = x; }
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
  bool is_character() const { return text_; }
  bool is_numeric() const { return !text_; }

  // The ravel. A one-element array's is in the value: a span of it lasts as long as the value
  // stays where it is (not moved).
  std::span<const double> numbers() const;
  std::span<const char32_t> characters() const;
  // Writable ravels: the storage is first copied when another value shares it.
  std::span<double> mutable_numbers();
  std::span<char32_t> mutable_characters();
  // The only element of a one-element array of numbers (a scalar or a vector of one).
  bool is_one_number() const { return one_ && !text_; }
  double one_number() const { return one_number_; }
  // Another number in a one-element array of numbers, its shape kept.
  void set_one_number(double x) { one_number_ = x; }
  // True when no other value shares the storage (it may then be written in place).
  bool unique() const;

  // The same ravel under another shape of the same element count (no copy).
  Value reshaped(Shape shape) const;
  // The characters as UTF-8 (the ravel in order).
  std::string utf8() const;

  // Same shape, same kind, same elements (exactly).
  friend bool operator==(const Value& a, const Value& b);

 private:
  Value(Shape shape, std::shared_ptr<Numbers> numbers)
      : shape_(std::move(shape)), ravel_(std::move(numbers)) {}
  Value(Shape shape, std::shared_ptr<Characters> characters)
      : shape_(std::move(shape)), ravel_(std::move(characters)), text_(true) {}
  Value(Shape shape, double x) : shape_(std::move(shape)), one_(true) { one_number_ = x; }
  Value(Shape shape, char32_t c) : shape_(std::move(shape)), text_(true), one_(true) {
    one_character_ = c;
  }
  Numbers& numbers_ravel() const { return *static_cast<Numbers*>(ravel_.get()); }
  Characters& characters_ravel() const { return *static_cast<Characters*>(ravel_.get()); }

  Shape shape_;
  std::shared_ptr<void> ravel_;  // Numbers or Characters (text_), unless `one_`
  union {
    double one_number_ = 0;
    char32_t one_character_;
  };
  bool text_ = false;  // characters
  bool one_ = false;   // one element, held in the value
};

}  // namespace igds::apl
