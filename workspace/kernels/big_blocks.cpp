#include "workspace/kernels/big_blocks.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <system_error>
#include <vector>

#include "workspace/kernels/parallel.h"

#ifdef __linux__
#include <malloc.h>
#include <sys/mman.h>
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23  // Linux 5.14
#endif
#endif

namespace igds::big_blocks {

#ifdef __linux__

namespace {

constexpr std::size_t huge_page = std::size_t(2) << 20;
// Addresses only (nothing is made present): far more than a session at the limit holds.
constexpr std::size_t reserved = std::size_t(64) << 30;

// Where the reserved addresses begin, once reserved: read by every delete of the program
// (owns), so a plain atomic, not a member of the pool behind its first-use guard.
constinit std::atomic<char*> base{nullptr};

// Makes the pages of [at, at + bytes) present; older kernels refuse the advice, and the pages are
// then written.
void make_present(void* at, std::size_t bytes) {
  if (madvise(at, bytes, MADV_POPULATE_WRITE) != 0) std::memset(at, 0, bytes);
}

// Part of one mapping (mremap moves only within one).
struct Piece {
  char* at;
  std::size_t bytes;
};

// The blocks' addresses are reserved once, as one range no page of which is present; a block is
// mapped inside it, made of pieces of kept memory moved there and fresh memory after them.
struct Pool {
  std::mutex mutex;
  bool tried = false;
  std::map<char*, std::size_t> unused;  // reserved addresses not mapped, runs merged
  std::vector<Piece> kept;
  std::map<char*, std::vector<Piece>> blocks;  // given, by address: their pieces
  std::size_t keep_limit = big_blocks::keep_limit;
  Figures figures;

  bool reserve() {
    if (tried) return base.load() != nullptr;
    tried = true;
    void* p = mmap(nullptr, reserved + huge_page, PROT_NONE,
                   MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) return false;
    auto* at = reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(p) + huge_page - 1) &
                                       ~std::uintptr_t(huge_page - 1));
    unused.emplace(at, reserved);
    base.store(at);
    return true;
  }

  // Addresses for `bytes` (a multiple of huge_page), the first run long enough; nullptr if none.
  char* take_addresses(std::size_t bytes) {
    for (auto it = unused.begin(); it != unused.end(); ++it) {
      if (it->second < bytes) continue;
      char* at = it->first;
      const std::size_t rest = it->second - bytes;
      unused.erase(it);
      if (rest > 0) unused.emplace(at + bytes, rest);
      return at;
    }
    return nullptr;
  }

  void give_addresses(char* at, std::size_t bytes) {
    auto next = unused.lower_bound(at);
    if (next != unused.end() && at + bytes == next->first) {
      bytes += next->second;
      next = unused.erase(next);
    }
    if (next != unused.begin()) {
      auto before = std::prev(next);
      if (before->first + before->second == at) {
        before->second += bytes;
        return;
      }
    }
    unused.emplace(at, bytes);
  }

  // Fresh memory at reserved addresses `at`, asked for as huge pages; false when the system gives
  // none (the addresses may then be unmapped: reserve_again).
  static bool map_fresh(char* at, std::size_t bytes) {
    if (mmap(at, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) !=
        at)
      return false;
    madvise(at, bytes, MADV_HUGEPAGE);  // advice: refused, the pages are small
    return true;
  }

  // The memory of `piece` back to the system, its addresses reserved again.
  void unmap(Piece piece) {
    if (mmap(piece.at, piece.bytes, PROT_NONE,
             MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE | MAP_FIXED, -1, 0) == piece.at)
      give_addresses(piece.at, piece.bytes);
  }

  // After a piece's pages were moved away its addresses are free to anyone: reserved again
  // unless another mapping took them meanwhile (then they are no longer the blocks'; nor when
  // they are still mapped, which only a failed mapping leaves).
  void reserve_again(char* at, std::size_t bytes) {
    void* p = mmap(at, bytes, PROT_NONE,
                   MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE | MAP_FIXED_NOREPLACE, -1, 0);
    if (p == at) {
      give_addresses(at, bytes);
    } else if (p != MAP_FAILED) {
      munmap(p, bytes);  // a kernel that took the flag for a hint
    }
  }

  void* allocate(std::size_t bytes) {
    const std::size_t size = (bytes + huge_page - 1) & ~(huge_page - 1);
    const std::lock_guard lock(mutex);
    if (!reserve()) return nullptr;
    // The smallest run of kept pieces side by side that holds the block, used where it is (a
    // block may span mappings; only a move must stay within one).
    std::sort(kept.begin(), kept.end(), [](const Piece& a, const Piece& b) { return a.at < b.at; });
    std::size_t best = kept.size(), best_bytes = 0;
    for (std::size_t first = 0, last = 0; first < kept.size(); first = last) {
      std::size_t run = kept[first].bytes;
      for (last = first + 1;
           last < kept.size() && kept[last - 1].at + kept[last - 1].bytes == kept[last].at; ++last)
        run += kept[last].bytes;
      if (run >= size && (best == kept.size() || run < best_bytes)) {
        best = first;
        best_bytes = run;
      }
    }
    if (best < kept.size()) {
      char* at = kept[best].at;
      std::vector<Piece> pieces;
      std::size_t filled = 0, k = best;
      while (filled < size) {
        Piece& from = kept[k];
        const std::size_t n = std::min(from.bytes, size - filled);
        pieces.push_back({from.at, n});
        from.at += n;
        from.bytes -= n;
        filled += n;
        ++k;
      }
      std::erase_if(kept, [](const Piece& piece) { return piece.bytes == 0; });
      figures.kept -= size;
      figures.used += size;
      blocks.emplace(at, std::move(pieces));
      return at;
    }
    char* at = take_addresses(size);
    if (!at) return nullptr;
    std::vector<Piece> pieces;
    std::size_t filled = 0;
    // The largest kept pieces first: fewer moves, fewer mappings.
    std::sort(kept.begin(), kept.end(),
              [](const Piece& a, const Piece& b) { return a.bytes < b.bytes; });
    while (filled < size && !kept.empty()) {
      Piece& from = kept.back();
      const std::size_t n = std::min(from.bytes, size - filled);
      if (mremap(from.at, n, n, MREMAP_MAYMOVE | MREMAP_FIXED, at + filled) == MAP_FAILED) break;
      reserve_again(from.at, n);
      from.at += n;
      from.bytes -= n;
      if (from.bytes == 0) kept.pop_back();
      pieces.push_back({at + filled, n});
      filled += n;
      figures.kept -= n;
      figures.moved += n;
    }
    if (filled < size) {
      char* rest = at + filled;
      const std::size_t n = size - filled;
      if (!map_fresh(rest, n)) {
        // No memory: what was moved stays kept, where it now is. A failed fixed mapping may
        // have left the rest's addresses unmapped: they are the blocks' only if reserved again.
        for (const Piece& piece : pieces) kept.push_back(piece);
        figures.kept += filled;
        reserve_again(rest, n);
        return nullptr;
      }
      pieces.push_back({rest, n});
      figures.fresh += n;
    }
    figures.used += size;
    blocks.emplace(at, std::move(pieces));
    return at;
  }

  void release(void* p) {
    const std::lock_guard lock(mutex);
    auto it = blocks.find(static_cast<char*>(p));
    if (it == blocks.end()) return;
    for (const Piece& piece : it->second) {
      kept.push_back(piece);
      figures.kept += piece.bytes;
      figures.used -= piece.bytes;
    }
    blocks.erase(it);
    trim();
  }

  // Kept memory beyond the limit back to the system, the smallest pieces first.
  void trim() {
    if (figures.kept <= keep_limit) return;
    std::sort(kept.begin(), kept.end(),
              [](const Piece& a, const Piece& b) { return a.bytes > b.bytes; });
    while (figures.kept > keep_limit && !kept.empty()) {
      figures.kept -= kept.back().bytes;
      unmap(kept.back());
      kept.pop_back();
    }
  }

  // See keep_ahead.
  std::size_t grow_kept(std::size_t bytes, const std::atomic<bool>& stop) {
    std::size_t added = 0;
    while (!stop.load(std::memory_order_relaxed)) {
      char* at;
      {
        const std::lock_guard lock(mutex);
        if (figures.kept >= std::min(bytes, keep_limit) || !reserve()) break;
        at = take_addresses(huge_page);
        if (!at) break;
      }
      if (!map_fresh(at, huge_page)) {
        const std::lock_guard lock(mutex);
        reserve_again(at, huge_page);
        break;
      }
      make_present(at, huge_page);
      const std::lock_guard lock(mutex);
      kept.push_back({at, huge_page});
      figures.kept += huge_page;
      figures.fresh += huge_page;
      added += huge_page;
    }
    return added;
  }
};

// Never destroyed: blocks may be released by the destructors of other static objects.
Pool& pool() {
  static Pool* const p = new Pool;
  return *p;
}

}  // namespace

void* allocate(std::size_t bytes) {
  if (bytes == 0 || bytes > reserved) return nullptr;
  return pool().allocate(bytes);
}

bool owns(const void* p) {
  const char* from = base.load(std::memory_order_relaxed);
  const auto* c = static_cast<const char*>(p);
  return from && c >= from && c < from + reserved;
}

void release(void* p) {
  pool().release(p);
}

void warm_heap(std::size_t bytes, const std::atomic<bool>* stop) {
  void* p = std::malloc(bytes);
  if (!p) return;
  const std::uintptr_t page = 4096;
  const auto from = (reinterpret_cast<std::uintptr_t>(p) + page - 1) & ~(page - 1);
  const auto to = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(page - 1);
  // 2 MB at a time, so that a stop is not kept waiting.
  for (std::uintptr_t at = from; at < to && !(stop && stop->load(std::memory_order_relaxed));
       at += huge_page)
    make_present(reinterpret_cast<void*>(at), std::min<std::uintptr_t>(huge_page, to - at));
  std::free(p);
}

std::size_t keep_ahead(std::size_t bytes, const std::atomic<bool>& stop) {
  return pool().grow_kept(bytes, stop);
}

void set_keep_limit(std::size_t bytes) {
  Pool& p = pool();
  const std::lock_guard lock(p.mutex);
  p.keep_limit = bytes;
  p.trim();
}

Figures figures() {
  Pool& p = pool();
  const std::lock_guard lock(p.mutex);
  return p.figures;
}

#else

void* allocate(std::size_t) {
  return nullptr;
}
void warm_heap(std::size_t, const std::atomic<bool>*) {}
std::size_t keep_ahead(std::size_t, const std::atomic<bool>&) {
  return 0;
}
bool owns(const void*) {
  return false;
}
void release(void*) {}
void set_keep_limit(std::size_t) {}
Figures figures() {
  return {};
}

#endif

Ahead::~Ahead() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void Ahead::want(std::size_t heap, std::size_t blocks, std::chrono::milliseconds after) {
  {
    const std::lock_guard lock(mutex_);
    if (heap == 0 && blocks == 0 && !thread_.joinable()) return;  // nothing yet, no thread
    heap_ = heap;
    blocks_ = blocks;
    after_ = after;
    wished_ = true;
    if (!thread_.joinable()) {
      try {
        thread_ = std::thread([this] { work(); });
      } catch (const std::system_error&) {
        wished_ = false;  // no thread: the memory comes when a command asks for it
        return;
      }
    }
  }
  wake_.notify_all();
}

void Ahead::wait_idle() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return !wished_ && !busy_; });
}

void Ahead::work() {
  lowest_priority();
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return wished_ || stop_; });
    if (stop_) break;
    const std::size_t heap = heap_, blocks = blocks_;
    wished_ = false;
    busy_ = true;
    if (after_.count() > 0 && wake_.wait_for(lock, after_, [&] { return wished_ || stop_; })) {
      busy_ = false;
      continue;  // stopped, or another wish
    }
    lock.unlock();
#ifdef __GLIBC__
    if (mallinfo2().fordblks < heap) warm_heap(heap, &stop_);
#endif
    keep_ahead(blocks, stop_);
    lock.lock();
    busy_ = false;
    idle_.notify_all();
  }
  busy_ = false;
  wished_ = false;
  idle_.notify_all();
}

}  // namespace igds::big_blocks
