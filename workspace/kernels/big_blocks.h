// The memory of large blocks (an image, INTPN, a plot's points), kept when freed and given again
// to the next large block whatever its size: the pages of freed blocks are moved, not copied, to
// where the new block is wanted (Linux's mremap), so the holes freed blocks leave never make igds
// ask the system for memory it already holds (docs/decisions.md, "Memory kept").
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>

namespace igds::big_blocks {

// Blocks of this many bytes or more are worth it (interp/main.cpp sends them here).
inline constexpr std::size_t smallest = std::size_t(2) << 20;
// Every block begins on a multiple of this.
inline constexpr std::size_t boundary = std::size_t(2) << 20;

// Memory for `bytes` bytes, aligned to 2 MB, its pages present where kept memory was moved in;
// nullptr when the system gives no room (the caller falls back to the heap). Thread-safe.
void* allocate(std::size_t bytes);

// Whether `p` lies among the blocks' addresses: given by allocate.
bool owns(const void* p);

// Keeps the memory of a block allocate gave for the next block; more than `keep_limit` kept
// goes back to the system.
void release(void* p);

inline constexpr std::size_t keep_limit = std::size_t(1) << 30;

// Another limit (tests), applied at once.
void set_keep_limit(std::size_t bytes);

// Makes `bytes` of the C library's heap, where the blocks below `smallest` come from, present
// and leaves it free there (igds keeps its heap: interp/main.cpp): done while igds waits, the
// next command's smaller blocks find memory ready instead of growing the heap page by page.
// `stop`, when given, is looked at every 2 MB.
void warm_heap(std::size_t bytes, const std::atomic<bool>* stop = nullptr);

// Grows the memory kept for the next blocks to `bytes` or more with fresh memory made present,
// 2 MB at a time, `stop` looked at between them; the bytes it added. No lock is held while the
// pages are made present: blocks are given and released meanwhile.
std::size_t keep_ahead(std::size_t bytes, const std::atomic<bool>& stop);

// Memory made ready while igds waits for a line (docs/decisions.md, "Memory made ready while
// igds waits for a line"): on a thread of its own at the lowest priority, the heap's free room
// made `heap` bytes (warm_heap) and the blocks' kept memory `blocks` bytes (keep_ahead). A wish
// made while one is being met replaces it once that one is met. The destructor stops the work
// between two steps and waits for it.
class Ahead {
 public:
  Ahead() = default;
  Ahead(const Ahead&) = delete;
  Ahead& operator=(const Ahead&) = delete;
  ~Ahead();
  // `after` this long, unless another wish comes first (which replaces it).
  void want(std::size_t heap, std::size_t blocks,
            std::chrono::milliseconds after = std::chrono::milliseconds(0));
  // Waits until every wish made so far is met (tests).
  void wait_idle();

 private:
  void work();
  std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::size_t heap_ = 0, blocks_ = 0;
  std::chrono::milliseconds after_{0};
  bool wished_ = false, busy_ = false;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// What the blocks hold now: for tests and the benchmark.
struct Figures {
  std::size_t used = 0;   // bytes of blocks given and not released
  std::size_t kept = 0;   // bytes kept for the next blocks
  std::size_t moved = 0;  // bytes of kept memory moved into new blocks, since the start
  std::size_t fresh = 0;  // bytes asked of the system, since the start
};
Figures figures();

}  // namespace igds::big_blocks
