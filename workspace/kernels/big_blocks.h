// The memory of large blocks (an image, INTPN, a plot's points), kept when freed and given again
// to the next large block whatever its size: the pages of freed blocks are moved, not copied, to
// where the new block is wanted (Linux's mremap), so the holes freed blocks leave never make igds
// ask the system for memory it already holds (docs/decisions.md, "Memory kept").
#pragma once

#include <cstddef>

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
void warm_heap(std::size_t bytes);

// What the blocks hold now: for tests and the benchmark.
struct Figures {
  std::size_t used = 0;   // bytes of blocks given and not released
  std::size_t kept = 0;   // bytes kept for the next blocks
  std::size_t moved = 0;  // bytes of kept memory moved into new blocks, since the start
  std::size_t fresh = 0;  // bytes asked of the system for new blocks, since the start
};
Figures figures();

}  // namespace igds::big_blocks
