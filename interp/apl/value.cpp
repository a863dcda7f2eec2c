#include "interp/apl/value.h"

#include <algorithm>
#include <utility>

#include "interp/apl/text.h"

namespace igds::apl {

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

Value::Value() : shape_{0}, numbers_(no_numbers()) {}

Value Value::number(double x) {
  return Value({}, std::make_shared<Numbers>(1, x), nullptr);
}

Value Value::character(char32_t c) {
  return Value({}, nullptr, std::make_shared<Characters>(1, c));
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
  return Value({chars.size()}, nullptr, std::make_shared<Characters>(chars.begin(), chars.end()));
}

Value Value::of_numbers(Shape shape, Numbers ravel) {
  return Value(std::move(shape), std::make_shared<Numbers>(std::move(ravel)), nullptr);
}

Value Value::of_numbers(Shape shape, std::span<const double> ravel) {
  return Value(std::move(shape), std::make_shared<Numbers>(ravel.begin(), ravel.end()), nullptr);
}

Value Value::of_characters(Shape shape, Characters ravel) {
  return Value(std::move(shape), nullptr, std::make_shared<Characters>(std::move(ravel)));
}

Value Value::uninitialised_numbers(Shape shape) {
  auto n = element_count(shape);
  return Value(std::move(shape), std::make_shared<Numbers>(n), nullptr);
}

Value Value::uninitialised_characters(Shape shape) {
  auto n = element_count(shape);
  return Value(std::move(shape), nullptr, std::make_shared<Characters>(n));
}

Value Value::zeros(Shape shape) {
  auto n = element_count(shape);
  return Value(std::move(shape), std::make_shared<Numbers>(n, 0.0), nullptr);
}

Value Value::blanks(Shape shape) {
  auto n = element_count(shape);
  return Value(std::move(shape), nullptr, std::make_shared<Characters>(n, U' '));
}

std::size_t Value::size() const {
  return numbers_ ? numbers_->size() : characters_->size();
}

std::span<const double> Value::numbers() const {
  if (!numbers_) return {};
  return {numbers_->data(), numbers_->size()};
}

std::span<const char32_t> Value::characters() const {
  if (!characters_) return {};
  return {characters_->data(), characters_->size()};
}

std::span<double> Value::mutable_numbers() {
  if (!numbers_) return {};
  if (numbers_.use_count() > 1) numbers_ = std::make_shared<Numbers>(*numbers_);
  return {numbers_->data(), numbers_->size()};
}

std::span<char32_t> Value::mutable_characters() {
  if (!characters_) return {};
  if (characters_.use_count() > 1) characters_ = std::make_shared<Characters>(*characters_);
  return {characters_->data(), characters_->size()};
}

bool Value::unique() const {
  return numbers_ ? numbers_.use_count() == 1 : characters_.use_count() == 1;
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
