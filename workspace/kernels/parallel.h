// Splitting a loop over rows between a few threads (the machine's cores; writing large grids is
// memory-bound and one core does not saturate the memory).
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace igds {

// The number of threads worth using for work on `items` numbers: 1 below a quarter of a million
// (a couple of milliseconds, where starting threads would cost as much), else the machine's
// cores (at most 8).
inline unsigned threads_for(std::size_t items) {
  if (items < (std::size_t(1) << 18)) return 1;
  return std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
}

// Calls f(first, last) on `threads` contiguous slices of [0, count), one per thread, the first
// slice on the calling thread. If a thread cannot be started its slice runs here; an exception
// thrown by any slice is rethrown here once every thread has finished.
template <class F>
void parallel_for(std::size_t count, unsigned threads, const F& f) {
  if (threads <= 1 || count < 2) {
    f(std::size_t(0), count);
    return;
  }
  std::vector<std::exception_ptr> errors(threads);
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (unsigned t = 1; t < threads; ++t) {
    const std::size_t first = count * t / threads, last = count * (t + 1) / threads;
    auto slice = [&f, &errors, t, first, last] {
      try {
        f(first, last);
      } catch (...) {
        errors[t] = std::current_exception();
      }
    };
    try {
      pool.emplace_back(slice);
    } catch (const std::system_error&) {
      slice();
    }
  }
  try {
    f(std::size_t(0), count / threads);
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

// Calls first() here and, at the same time, second() on a second thread when `together`; one
// after the other, here, when not (or when no thread can be started). An exception thrown by
// either is rethrown here once both have finished.
template <class First, class Second>
void both(bool together, const First& first, const Second& second) {
  parallel_for(2, together ? 2 : 1, [&](std::size_t from, std::size_t to) {
    for (std::size_t part = from; part < to; ++part) {
      if (part == 0)
        first();
      else
        second();
    }
  });
}

// The number of items, from the first, whose weights add up to half the weights of all `count`
// items or just more: where a list is cut in two parts of about the same work.
template <class Weight>
std::size_t halfway(std::size_t count, const Weight& weight) {
  std::size_t total = 0;
  for (std::size_t k = 0; k < count; ++k) total += weight(k);
  std::size_t k = 0;
  for (std::size_t half = 0; k < count && 2 * half < total; ++k) half += weight(k);
  return k;
}

}  // namespace igds
