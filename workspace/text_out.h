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
  // written there end.
  char* room(std::size_t n) {
    if (static_cast<std::size_t>(end_ - at_) < n) hand_on(n);
    return at_;
  }
  void commit(char* end) { at_ = end; }
  // All the room there is at once, at least n (at most max_room) bytes: [first, first + size).
  struct Space {
    char* first;
    std::size_t size;
  };
  Space space(std::size_t n) {
    room(n);
    return {at_, static_cast<std::size_t>(end_ - at_)};
  }

  void put(char c) { *room(1) = c, ++at_; }
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

// A text made aside in pieces of a megabyte, then put into another TextOut: the later half of a
// large plot or document, made on a second thread while the first half goes into the file (a
// string would be copied each time it grew). Written in order only (no seek).
class PiecesOut final : public TextOut {
 public:
  PiecesOut();
  // The text so far into `out`.
  void put_into(TextOut& out) const;

 private:
  void take(std::size_t n) override;
  std::unique_ptr<char[]> open_;
  std::vector<std::pair<std::unique_ptr<char[]>, std::size_t>> done_;
};

// Room for put_each's items made aside, kept from one call to the next.
struct Aside {
  std::unique_ptr<char[]> bytes;
  std::size_t size = 0;
};

// Puts into `out`, in order, the texts of items 0 .. count - 1, each written by
// make(char* w, i) at w (at most `most` bytes, most <= TextOut::max_room) and ending where it
// returns. With `threads` 2, block by block (a few megabytes of text each), the calling thread
// makes the first half of a block straight into `out` while a second makes the rest into
// `aside`, which is then put: the same text, in about half the time when making it is the work.
template <class Make>
void put_each(TextOut& out, std::size_t count, std::size_t most, unsigned threads, Aside& aside,
              const Make& make) {
  put_each(out, count, most, threads, aside, std::size_t{8} << 20, make);
}

// The same with blocks of about `block_bytes` of text (at least two items each).
template <class Make>
void put_each(TextOut& out, std::size_t count, std::size_t most, unsigned threads, Aside& aside,
              std::size_t block_bytes, const Make& make) {
  const std::size_t block = threads > 1 ? std::max<std::size_t>(2, block_bytes / most) : count;
  for (std::size_t first = 0; first < count; first += block) {
    const std::size_t last = std::min(count, first + block);
    const std::size_t half = threads > 1 ? first + (last - first) / 2 : last;
    if (half < last && aside.size < (last - half) * most) {
      aside.size = (last - half) * most;
      aside.bytes = std::make_unique_for_overwrite<char[]>(aside.size);
    }
    char* aside_end = aside.bytes.get();
    both(
        half < last,
        [&] {
          for (std::size_t i = first; i < half; ++i) out.commit(make(out.room(most), i));
        },
        [&] {
          char* w = aside.bytes.get();
          for (std::size_t i = half; i < last; ++i) w = make(w, i);
          aside_end = w;
        });
    out.put(std::string_view(aside.bytes.get(),
                             static_cast<std::size_t>(aside_end - aside.bytes.get())));
  }
}

}  // namespace igds
