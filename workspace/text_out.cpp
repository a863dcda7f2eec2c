#include "workspace/text_out.h"

#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "workspace/kernels/interrupt.h"
#include "workspace/kernels/parallel.h"

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

void TextOut::put_runs(std::span<const std::string_view> runs) {
  for (std::string_view run : runs) put(run);
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
  std::vector<std::string_view> runs;
  runs.reserve(done_.size() + 1);
  for (const auto& [bytes, size] : done_) runs.emplace_back(bytes.get(), size);
  runs.emplace_back(begin_, static_cast<std::size_t>(at_ - begin_));
  out.put_runs(runs);
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

void put_in_order(TextOut& out, std::size_t texts,
                  const std::function<void(std::size_t, TextOut&)>& make) {
  const unsigned helpers = cores() - 1;
  const std::size_t window = 4 * (std::size_t{helpers} + 1);  // texts begun and not yet put
  struct Slot {
    PiecesOut text;
    bool made = false;
    std::exception_ptr error;
  };
  std::vector<Slot> slots(std::min(window, texts));
  std::mutex mutex;
  std::condition_variable changed;
  std::size_t begun = 0, put = 0;  // texts begun; texts put into out
  bool stop = false;
  // Makes text k aside, into its slot.
  auto make_aside = [&](std::size_t k) {
    Slot& slot = slots[k % slots.size()];
    try {
      make(k, slot.text);
    } catch (...) {
      slot.error = std::current_exception();
    }
  };
  auto helper = [&] {
    std::unique_lock lock(mutex);
    for (;;) {
      changed.wait(lock, [&] { return stop || begun == texts || begun < put + slots.size(); });
      if (stop || begun == texts) return;
      const std::size_t k = begun++;
      lock.unlock();
      make_aside(k);
      lock.lock();
      slots[k % slots.size()].made = true;
      changed.notify_all();
    }
  };
  std::vector<std::thread> pool;
  // The helpers are stopped and joined however this returns.
  struct Joined {
    std::vector<std::thread>& pool;
    std::mutex& mutex;
    std::condition_variable& changed;
    bool& stop;
    ~Joined() {
      {
        const std::lock_guard lock(mutex);
        stop = true;
      }
      changed.notify_all();
      for (std::thread& t : pool) t.join();
    }
  } joined{pool, mutex, changed, stop};
  pool.reserve(helpers);
  for (unsigned t = 0; t < helpers; ++t) {
    try {
      pool.emplace_back(helper);
    } catch (const std::system_error&) {
      break;  // fewer helpers: this thread makes the rest
    }
  }
  std::unique_lock lock(mutex);
  while (put < texts) {
    Slot& next = slots[put % slots.size()];
    if (next.made) {
      lock.unlock();
      if (next.error) std::rethrow_exception(next.error);
      if (put > 0) check_interrupt();
      next.text.put_into(out);
      next.text.clear();
      lock.lock();
      next.made = false;
      ++put;
      changed.notify_all();
    } else if (begun == put) {
      // The next text is not begun: made here, straight into out.
      ++begun;
      lock.unlock();
      if (put > 0) check_interrupt();
      make(put, out);
      lock.lock();
      ++put;
      changed.notify_all();
    } else if (begun < texts && begun < put + slots.size()) {
      // The next is being made by a helper: another made here meanwhile.
      const std::size_t k = begun++;
      lock.unlock();
      make_aside(k);
      lock.lock();
      slots[k % slots.size()].made = true;
    } else {
      changed.wait(lock);
    }
  }
}

}  // namespace igds
