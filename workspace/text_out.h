// A text made piece by piece: the writers of files of hundreds of megabytes (EXPORT, WRITE) put
// their bytes into a buffer that is handed on whenever it fills, to a file being written
// (disk::write_file) or to a string, so that no copy of the whole text is ever held.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "workspace/kernels/interrupt.h"
#include "workspace/kernels/parallel.h"

namespace igds {

class TextOut {
 public:
  // The most room(n) may ask for at once.
  static constexpr std::size_t max_room = 4096;

  virtual ~TextOut() = default;
  TextOut(const TextOut&) = delete;
  TextOut& operator=(const TextOut&) = delete;

  // Room for n (at most max_room) bytes at the pointer returned; commit(end) says where the bytes
  // written there end. A writer that went past the room it asked for is a fault of igds: commit
  // throws std::logic_error (before another byte is written) rather than let it go unseen.
  char* room(std::size_t n) {
    if (static_cast<std::size_t>(end_ - at_) < n) hand_on(n);
    room_end_ = at_ + n;
    return at_;
  }
  void commit(char* end) {
    if (end < at_ || end > room_end_) overran();
    at_ = end;
  }
  // All the room there is at once, at least n (at most max_room) bytes: [first, first + size).
  struct Space {
    char* first;
    std::size_t size;
  };
  Space space(std::size_t n) {
    room(n);
    room_end_ = end_;
    return {at_, static_cast<std::size_t>(end_ - at_)};
  }

  void put(char c) {
    if (at_ == end_) hand_on(1);
    *at_++ = c;
  }
  void put(std::string_view bytes);     // any length
  void put(char c, std::size_t count);  // `count` copies of c
  std::uint64_t offset() const { return base_ + std::uint64_t(at_ - begin_); }  // the next byte's
  std::uint64_t size() const;  // the text's length so far

  // `n` bytes to be written later (after seek(offset) to them); the text goes on after them.
  void skip(std::size_t n) { seek(offset() + n); }
  // The next bytes go at `offset`, within what was written or skipped or at the end. A text must
  // have every skipped byte written by the time it is finished.
  void seek(std::uint64_t offset);

 protected:
  TextOut() = default;
  // Takes the bytes [begin_, at_), which belong at base_, and sets begin_ = at_ to fresh room
  // of at least n bytes up to end_. The caller moves base_.
  virtual void take(std::size_t n) = 0;
  char* begin_ = nullptr;
  char* at_ = nullptr;
  char* end_ = nullptr;
  std::uint64_t base_ = 0;

 private:
  void hand_on(std::size_t n);
  [[noreturn]] static void overran();
  char* room_end_ = nullptr;      // the end of the room last asked for
  std::uint64_t end_offset_ = 0;  // the largest offset handed on so far
};

// A TextOut into a string.
class StringOut final : public TextOut {
 public:
  StringOut();
  // The text, once it is finished (every skipped byte written).
  std::string take_text();

 private:
  void take(std::size_t n) override;
  std::string text_;
  std::vector<char> buffer_;
};

// A text made aside in pieces of a megabyte, then put into another TextOut: a part of a large
// text made on another thread while the first part goes into the file (a string would be copied
// each time it grew). Written in order only (no seek).
class PiecesOut final : public TextOut {
 public:
  PiecesOut();
  // The text so far into `out`.
  void put_into(TextOut& out) const;
  // Empty again, its first piece kept.
  void clear();

 private:
  void take(std::size_t n) override;
  std::unique_ptr<char[]> open_;
  std::vector<std::pair<std::unique_ptr<char[]>, std::size_t>> done_;
};

// Puts into `out`, in order, the texts of items 0 .. count - 1, each written by make(char* w, k)
// at w in at most `most` bytes (most <= TextOut::max_room) and ending where it returns. The
// writers' one way of using the machine's cores: a large text is made block by block (a few
// megabytes of text each), the calling thread making the first part of a block straight into
// `out` while other threads (parallel.h) make the other parts into texts of their own, put
// after it: the same text as on one thread. A Ctrl-C waiting stops it between blocks
// (kernels/interrupt.h): a text of one block, as most are, costs no look for one.
template <class Make>
void put_each(TextOut& out, std::size_t count, std::size_t most, const Make& make) {
  constexpr std::size_t block_bytes = std::size_t{8} << 20;
  auto items = [&](TextOut& to, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      char* w = to.room(most);
      to.commit(make(w, k));
    }
  };
  const unsigned threads = count > 1 && count * most >= block_bytes / 2 ? cores() : 1;
  const std::size_t block =
      threads > 1 ? std::max<std::size_t>(threads, block_bytes / most) : count;
  std::vector<PiecesOut> others(threads - 1);
  for (std::size_t first = 0; first < count; first += block) {
    if (first > 0) check_interrupt();
    const std::size_t last = std::min(count, first + block);
    const std::size_t n = last - first;
    in_parallel(threads, [&](unsigned t) {
      items(t == 0 ? out : others[t - 1], first + n * t / threads, first + n * (t + 1) / threads);
    });
    for (PiecesOut& text : others) {
      text.put_into(out);
      text.clear();
    }
  }
}

}  // namespace igds
