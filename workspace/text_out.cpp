#include "workspace/text_out.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace igds {

void TextOut::hand_on(std::size_t n) {
  const std::uint64_t next = offset();
  take(n);
  base_ = next;
  end_offset_ = std::max(end_offset_, next);
}

void TextOut::overran() {
  throw std::logic_error("a writer wrote past the room it asked for");
}

void TextOut::put(std::string_view bytes) {
  while (!bytes.empty()) {
    if (at_ == end_) hand_on(1);
    const std::size_t n = std::min(bytes.size(), static_cast<std::size_t>(end_ - at_));
    std::memcpy(at_, bytes.data(), n);
    at_ += n;
    bytes.remove_prefix(n);
  }
}

void TextOut::put(char c, std::size_t count) {
  while (count > 0) {
    if (at_ == end_) hand_on(1);
    const std::size_t n = std::min(count, static_cast<std::size_t>(end_ - at_));
    std::memset(at_, c, n);
    at_ += n;
    count -= n;
  }
}

std::uint64_t TextOut::size() const {
  return std::max(end_offset_, offset());
}

void TextOut::seek(std::uint64_t offset) {
  hand_on(0);
  base_ = offset;
}

StringOut::StringOut() : buffer_(std::size_t{1} << 16) {
  begin_ = at_ = buffer_.data();
  end_ = begin_ + buffer_.size();
}

void StringOut::take(std::size_t n) {
  const auto length = static_cast<std::size_t>(at_ - begin_);
  const auto at = static_cast<std::size_t>(base_);
  if (text_.size() < at + length) text_.resize(at + length);
  std::memcpy(text_.data() + at, begin_, length);
  if (buffer_.size() < n) buffer_.resize(n);
  begin_ = at_ = buffer_.data();
  end_ = begin_ + buffer_.size();
}

std::string StringOut::take_text() {
  const std::uint64_t length = size();
  seek(offset());
  text_.resize(static_cast<std::size_t>(length));
  return std::move(text_);
}

namespace {
constexpr std::size_t piece = std::size_t{1} << 20;
}

PiecesOut::PiecesOut() {
  take(0);
}

void PiecesOut::put_into(TextOut& out) const {
  for (const auto& [bytes, size] : done_) out.put(std::string_view(bytes.get(), size));
  out.put(std::string_view(begin_, static_cast<std::size_t>(at_ - begin_)));
}

void PiecesOut::clear() {
  done_.clear();
  begin_ = at_ = open_.get();
  base_ = 0;
}

void PiecesOut::take(std::size_t) {
  if (at_ != begin_) done_.push_back({std::move(open_), static_cast<std::size_t>(at_ - begin_)});
  if (!open_) open_ = std::make_unique_for_overwrite<char[]>(piece);
  begin_ = at_ = open_.get();
  end_ = begin_ + piece;
}

}  // namespace igds
