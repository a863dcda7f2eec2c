#include "interp/apl/value.h"

#include <algorithm>
#include <utility>

#include "interp/apl/text.h"

namespace igds::apl {

void Shape::reserve(std::size_t n) {
  if (n <= capacity_) return;
  auto bigger = std::make_unique<std::size_t[]>(n);
  std::copy(begin(), end(), bigger.get());
  big_ = std::move(bigger);
  capacity_ = n;
}

void Shape::resize(std::size_t n, std::size_t length) {
  reserve(n);
  if (n > size_) std::fill(data() + size_, data() + n, length);
  size_ = n;
}

void Shape::push_back(std::size_t length) {
  if (size_ == capacity_) reserve(2 * capacity_);
  data()[size_++] = length;
}

Shape::iterator Shape::insert(const_iterator at, std::size_t length) {
  const std::size_t k = static_cast<std::size_t>(at - begin());
  push_back(length);
  std::rotate(begin() + k, end() - 1, end());
  return begin() + k;
}

Shape::iterator Shape::erase(const_iterator first, const_iterator last) {
  const std::size_t k = static_cast<std::size_t>(first - begin());
  const std::size_t n = static_cast<std::size_t>(last - first);
  std::copy(begin() + k + n, end(), begin() + k);
  size_ -= n;
  return begin() + k;
}

std::size_t element_count(const Shape& shape) {
  std::size_t n = 1;
  for (auto d : shape) n *= d;
  return n;
}

namespace {
// One empty ravel shared by every default value (written only after a copy).
const std::shared_ptr<Numbers>& no_numbers() {
  static const auto empty = std::make_shared<Numbers>();
  return empty;
}
}  // namespace

Value::Value() : shape_{0}, ravel_(no_numbers()) {}

Value Value::character(char32_t c) {
  return Value({}, c);
}

Value Value::vector(std::initializer_list<double> xs) {
  return of_numbers({xs.size()}, std::span<const double>(xs.begin(), xs.size()));
}

Value Value::vector(std::span<const double> xs) {
  return of_numbers({xs.size()}, xs);
}

Value Value::text(std::string_view utf8) {
  return text(decode_utf8(utf8));
}

Value Value::text(std::u32string_view chars) {
  if (chars.size() == 1) return Value({1}, chars[0]);
  return Value({chars.size()}, std::make_shared<Characters>(chars.begin(), chars.end()));
}

Value Value::of_numbers(Shape shape, Numbers ravel) {
  if (ravel.size() == 1) return Value(std::move(shape), ravel[0]);
  return Value(std::move(shape), std::make_shared<Numbers>(std::move(ravel)));
}

Value Value::of_numbers(Shape shape, std::span<const double> ravel) {
  if (ravel.size() == 1) return Value(std::move(shape), ravel[0]);
  return Value(std::move(shape), std::make_shared<Numbers>(ravel.begin(), ravel.end()));
}

Value Value::of_characters(Shape shape, Characters ravel) {
  if (ravel.size() == 1) return Value(std::move(shape), ravel[0]);
  return Value(std::move(shape), std::make_shared<Characters>(std::move(ravel)));
}

Value Value::uninitialised_numbers(Shape shape) {
  auto n = element_count(shape);
  if (n == 1) return Value(std::move(shape), 0.0);
  return Value(std::move(shape), std::make_shared<Numbers>(n));
}

Value Value::uninitialised_characters(Shape shape) {
  auto n = element_count(shape);
  if (n == 1) return Value(std::move(shape), U' ');
  return Value(std::move(shape), std::make_shared<Characters>(n));
}

Value Value::zeros(Shape shape) {
  auto n = element_count(shape);
  if (n == 1) return Value(std::move(shape), 0.0);
  return Value(std::move(shape), std::make_shared<Numbers>(n, 0.0));
}

Value Value::blanks(Shape shape) {
  auto n = element_count(shape);
  if (n == 1) return Value(std::move(shape), U' ');
  return Value(std::move(shape), std::make_shared<Characters>(n, U' '));
}

std::size_t Value::size() const {
  if (one_) return 1;
  return text_ ? characters_ravel().size() : numbers_ravel().size();
}

std::span<const double> Value::numbers() const {
  if (text_) return {};
  if (one_) return {&one_number_, 1};
  return {numbers_ravel().data(), numbers_ravel().size()};
}

std::span<const char32_t> Value::characters() const {
  if (!text_) return {};
  if (one_) return {&one_character_, 1};
  return {characters_ravel().data(), characters_ravel().size()};
}

std::span<double> Value::mutable_numbers() {
  if (text_) return {};
  if (one_) return {&one_number_, 1};
  if (ravel_.use_count() > 1) ravel_ = std::make_shared<Numbers>(numbers_ravel());
  return {numbers_ravel().data(), numbers_ravel().size()};
}

std::span<char32_t> Value::mutable_characters() {
  if (!text_) return {};
  if (one_) return {&one_character_, 1};
  if (ravel_.use_count() > 1) ravel_ = std::make_shared<Characters>(characters_ravel());
  return {characters_ravel().data(), characters_ravel().size()};
}

bool Value::unique() const {
  return one_ || ravel_.use_count() == 1;
}

Value Value::reshaped(Shape shape) const {
  Value v = *this;
  v.shape_ = std::move(shape);
  return v;
}

std::string Value::utf8() const {
  auto c = characters();
  return encode_utf8(std::u32string_view(c.data(), c.size()));
}

bool operator==(const Value& a, const Value& b) {
  if (a.shape_ != b.shape_ || a.is_character() != b.is_character()) return false;
  if (a.is_character()) return std::ranges::equal(a.characters(), b.characters());
  return std::ranges::equal(a.numbers(), b.numbers());
}

}  // namespace igds::apl
