// A text made piece by piece: the writers of files of hundreds of megabytes (EXPORT, WRITE) put
// their bytes into a buffer that is handed on whenever it fills, to a file being written
// (disk::write_file) or to a string, so that no copy of the whole text is ever held.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

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
  // The runs one after the other, as put(run) for each; a file takes them from where they are,
  // without a copy into its buffer (disk::write_file).
  virtual void put_runs(std::span<const std::string_view> runs);
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

// A text made aside in pieces of a megabyte, then put into another TextOut: one of
// put_in_order's texts, made on one thread while another puts those before it into the file (a
// string would be copied each time it grew). Written in order only (no seek).
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

// The room of one text of put_each's: about this many bytes of items' room each.
inline constexpr std::size_t put_each_text_bytes = std::size_t{1} << 20;

// Puts into `out`, in order, texts 0 .. texts - 1, text k made by make(k, to): the writers' one
// way of using the machine's cores. The calling thread and cores() - 1 threads, started for the
// call and joined before it returns, each take the next text not yet begun; a text is made
// straight into `out` when it is the next to go there, else into a TextOut of its own, put into
// `out` when its turn comes (at most 4 texts a thread made ahead). The calling thread puts them
// in order, and makes one whenever none is ready to put. A Ctrl-C waiting stops it before any
// text but the first (kernels/interrupt.h); an exception from any text is rethrown here.
void put_in_order(TextOut& out, std::size_t texts,
                  const std::function<void(std::size_t, TextOut&)>& make);

// Puts into `out`, in order, the texts of items 0 .. count - 1, each written by make(char* w, k)
// at w in at most `most` bytes (most <= TextOut::max_room) and ending where it returns. A text of
// 4 MB of room or more is made on the cores by put_in_order, in texts of about
// put_each_text_bytes of room; the same text as on one thread. A smaller one, as most are, is
// made here whole, and costs no look for a Ctrl-C.
template <class Make>
void put_each(TextOut& out, std::size_t count, std::size_t most, const Make& make) {
  auto items = [&](TextOut& to, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      char* w = to.room(most);
      to.commit(make(w, k));
    }
  };
  if (count < 2 || count * most < (std::size_t{4} << 20)) {
    items(out, 0, count);
    return;
  }
  const std::size_t per = std::max<std::size_t>(1, put_each_text_bytes / most);
  put_in_order(out, (count + per - 1) / per, [&](std::size_t k, TextOut& to) {
    items(to, k * per, std::min(count, (k + 1) * per));
  });
}

}  // namespace igds
