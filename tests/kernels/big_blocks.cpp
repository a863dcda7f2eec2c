// The memory of large blocks, kept and given again (big_blocks.h).
#include "workspace/kernels/big_blocks.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#ifdef __linux__
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

using namespace igds;

namespace {

constexpr std::size_t MB = std::size_t(1) << 20;

// Whether every page of [p, p + bytes) is present in memory.
bool present([[maybe_unused]] const void* p, [[maybe_unused]] std::size_t bytes) {
#ifdef __linux__
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const auto at = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t from = at & ~(page - 1), to = (at + bytes + page - 1) & ~(page - 1);
  std::vector<unsigned char> in((to - from) / page);
  if (mincore(reinterpret_cast<void*>(from), to - from, in.data()) != 0) return false;
  for (unsigned char c : in)
    if (!(c & 1)) return false;
  return true;
#else
  return false;
#endif
}

bool all(const void* p, std::size_t bytes, unsigned char value) {
  const auto* c = static_cast<const unsigned char*>(p);
  for (std::size_t k = 0; k < bytes; ++k)
    if (c[k] != value) return false;
  return true;
}

// The memory earlier tests left kept, held until the end of a test (so that a test's blocks
// are the only ones kept).
struct Held {
  void* block = nullptr;
  explicit Held(void* p) : block(p) {}
  Held(const Held&) = delete;
  ~Held() {
    if (block) big_blocks::release(block);
  }
};

Held hold_kept() {
  const std::size_t left = big_blocks::figures().kept;
  return Held(left > 0 ? big_blocks::allocate(left) : nullptr);
}

}  // namespace

#ifdef __linux__

TEST_CASE("a large block freed is given again, where it is, to the next block it holds") {
  const Held others = hold_kept();
  void* a = big_blocks::allocate(8 * MB);
  REQUIRE(a != nullptr);
  CHECK(reinterpret_cast<std::uintptr_t>(a) % (2 * MB) == 0);
  CHECK(big_blocks::owns(a));
  std::memset(a, 7, 8 * MB);
  const auto before = big_blocks::figures();
  big_blocks::release(a);
  CHECK(big_blocks::figures().kept == before.kept + 8 * MB);
  void* b = big_blocks::allocate(6 * MB + 1);  // 8 MB in whole huge pages
  CHECK(b == a);
  const auto after = big_blocks::figures();
  CHECK(after.fresh == before.fresh);
  CHECK(after.used == before.used);
  CHECK(all(b, 6 * MB, 7));  // the same pages: not cleared
  big_blocks::release(b);
}

TEST_CASE("blocks freed side by side make a larger block where they are") {
  const Held others = hold_kept();
  auto* a = static_cast<char*>(big_blocks::allocate(8 * MB));
  auto* b = static_cast<char*>(big_blocks::allocate(8 * MB));
  REQUIRE((a && b));
  REQUIRE(b == a + 8 * MB);  // fresh addresses, one after the other
  std::memset(a, 1, 8 * MB);
  std::memset(b, 2, 8 * MB);
  big_blocks::release(a);
  big_blocks::release(b);
  const auto before = big_blocks::figures();
  auto* c = static_cast<char*>(big_blocks::allocate(16 * MB));
  CHECK(c == a);
  const auto after = big_blocks::figures();
  CHECK(after.moved == before.moved);
  CHECK(after.fresh == before.fresh);
  CHECK((all(c, 8 * MB, 1) && all(c + 8 * MB, 8 * MB, 2)));
  // Freed again, it is one run of kept memory however it was made.
  big_blocks::release(c);
  CHECK(big_blocks::allocate(16 * MB) == c);
  big_blocks::release(c);
}

TEST_CASE("blocks freed apart make a larger block: their pages are moved, not asked for again") {
  // Only the two blocks below are kept.
  const Held others = hold_kept();
  void* a = big_blocks::allocate(8 * MB);
  void* between = big_blocks::allocate(8 * MB);
  void* b = big_blocks::allocate(8 * MB);
  REQUIRE((a && between && b));
  std::memset(a, 1, 8 * MB);
  std::memset(b, 2, 8 * MB);
  big_blocks::release(a);
  big_blocks::release(b);
  const auto kept = big_blocks::figures();
  REQUIRE(kept.kept == 16 * MB);

  auto* c = static_cast<unsigned char*>(big_blocks::allocate(16 * MB));
  REQUIRE(c != nullptr);
  const auto after = big_blocks::figures();
  CHECK(after.fresh == kept.fresh);
  CHECK(after.moved == kept.moved + 16 * MB);
  CHECK(after.kept == 0);
  CHECK(present(c, 16 * MB));
  // Each half is one of the blocks freed, its bytes as they were.
  CHECK(((all(c, 8 * MB, 1) && all(c + 8 * MB, 8 * MB, 2)) ||
         (all(c, 8 * MB, 2) && all(c + 8 * MB, 8 * MB, 1))));
  std::memset(c, 3, 16 * MB);  // and writable

  // A block larger than what is kept: the kept memory first, fresh memory after it.
  big_blocks::release(c);
  void* d = big_blocks::allocate(24 * MB);
  REQUIRE(d != nullptr);
  const auto last = big_blocks::figures();
  CHECK(last.moved == after.moved + 16 * MB);
  CHECK(last.fresh == after.fresh + 8 * MB);
  CHECK(all(d, 16 * MB, 3));
  CHECK(all(static_cast<unsigned char*>(d) + 16 * MB, 8 * MB, 0));
  big_blocks::release(d);
  big_blocks::release(between);
}

TEST_CASE("kept memory beyond the limit goes back to the system") {
  big_blocks::set_keep_limit(8 * MB);
  CHECK(big_blocks::figures().kept <= 8 * MB);
  void* a = big_blocks::allocate(8 * MB);
  void* b = big_blocks::allocate(8 * MB);
  REQUIRE((a && b));
  std::memset(a, 1, 8 * MB);
  std::memset(b, 1, 8 * MB);
  big_blocks::release(a);
  big_blocks::release(b);
  CHECK(big_blocks::figures().kept == 8 * MB);
  // The memory given back is gone from the process; its addresses serve again.
  CHECK((!present(a, 8 * MB) || !present(b, 8 * MB)));
  big_blocks::set_keep_limit(big_blocks::keep_limit);
  void* c = big_blocks::allocate(16 * MB);
  REQUIRE(c != nullptr);
  std::memset(c, 2, 16 * MB);
  big_blocks::release(c);
}

TEST_CASE("only the blocks' own addresses are theirs; nothing is given for nothing") {
  CHECK(big_blocks::allocate(0) == nullptr);
  CHECK(big_blocks::allocate(std::size_t(1) << 40) == nullptr);  // beyond the addresses reserved
  void* heap = std::malloc(16);
  CHECK_FALSE(big_blocks::owns(heap));
  CHECK_FALSE(big_blocks::owns(nullptr));
  big_blocks::release(heap);  // not a block: nothing happens
  std::free(heap);
  std::vector<char> local(8 * MB);
  CHECK_FALSE(big_blocks::owns(local.data()));
}

// The C library's heap (not a sanitizer's allocator, which keeps its own).
#ifndef IGDS_SANITIZED
TEST_CASE("the heap warmed ahead gives present memory to the next smaller blocks") {
  // The heap as igds sets it (interp/main.cpp): every block from it, nothing given back.
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  big_blocks::warm_heap(8 * MB);
  void* p = std::malloc(6 * MB);
  REQUIRE(p != nullptr);
  CHECK(present(p, 6 * MB));  // before anything is written to it
  std::free(p);
  mallopt(M_MMAP_MAX, 65536);  // glibc's defaults again
  mallopt(M_TRIM_THRESHOLD, 128 * 1024);
}
#endif

TEST_CASE("memory kept ahead is present, and the next block takes it instead of fresh memory") {
  const Held others = hold_kept();
  const std::atomic<bool> go{false}, stop{true};
  CHECK(big_blocks::keep_ahead(8 * MB, stop) == 0);  // stopped before the first step
  CHECK(big_blocks::figures().kept == 0);
  CHECK(big_blocks::keep_ahead(7 * MB, go) == 8 * MB);  // in whole huge pages
  const auto before = big_blocks::figures();
  CHECK(before.kept == 8 * MB);
  CHECK(big_blocks::keep_ahead(8 * MB, go) == 0);  // kept already
  void* p = big_blocks::allocate(8 * MB);
  REQUIRE(p != nullptr);
  CHECK(present(p, 8 * MB));  // before anything is written to it
  const auto after = big_blocks::figures();
  CHECK(after.fresh == before.fresh);
  CHECK(after.kept == 0);
  big_blocks::release(p);
}

TEST_CASE("memory is made ready on a thread of its own, to the last wish") {
  const Held others = hold_kept();
  {
    big_blocks::Ahead ahead;
    ahead.want(0, 4 * MB);
    ahead.want(0, 12 * MB);  // replaces the first, or follows it
    ahead.wait_idle();
    CHECK(big_blocks::figures().kept == 12 * MB);
    ahead.want(0, 6 * MB);  // kept already: nothing more
    ahead.wait_idle();
    CHECK(big_blocks::figures().kept == 12 * MB);
    ahead.want(0, 256 * MB);  // the destructor stops it between two steps
  }
  const auto left = big_blocks::figures();
  CHECK(left.kept >= 12 * MB);
  CHECK(left.kept <= 256 * MB);
  // Stopped and joined: nothing is made after the destructor.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  CHECK(big_blocks::figures().kept == left.kept);
  // What it made goes to the next blocks.
  const Held made = hold_kept();
  CHECK(big_blocks::figures().kept == 0);
  {
    big_blocks::Ahead ahead;
    ahead.want(0, 16 * MB, std::chrono::hours(1));
    ahead.want(0, 6 * MB);  // comes first: the wish waiting its hour is replaced
    ahead.wait_idle();
    CHECK(big_blocks::figures().kept == 6 * MB);
    ahead.want(0, 10 * MB, std::chrono::milliseconds(20));  // met once its time has come
    ahead.wait_idle();
    CHECK(big_blocks::figures().kept == 10 * MB);
    ahead.want(0, 64 * MB, std::chrono::hours(1));  // the destructor does not wait for it
  }
  CHECK(big_blocks::figures().kept == 10 * MB);
}

TEST_CASE("threads take and free blocks at once, each block its own") {
  const auto before = big_blocks::figures();
  std::vector<std::thread> threads;
  std::vector<int> wrong(4, 0);
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([t, &wrong] {
      for (int round = 0; round < 20; ++round) {
        const std::size_t bytes = (4 + (t + round) % 5) * MB;
        auto* p = static_cast<unsigned char*>(big_blocks::allocate(bytes));
        if (!p) {
          ++wrong[t];
          continue;
        }
        std::memset(p, t + 1, bytes);
        std::this_thread::yield();
        if (!all(p, bytes, static_cast<unsigned char>(t + 1))) ++wrong[t];
        big_blocks::release(p);
      }
    });
  for (auto& th : threads) th.join();
  CHECK(wrong == std::vector<int>(4, 0));
  CHECK(big_blocks::figures().used == before.used);
}

#endif
