// The one way igds splits a computation between threads (docs/architecture.md, "Threads"): a
// loop over the rows of a grid of millions of points cut into as many parts as the machine has
// cores (the text of a large file is made by workspace/text_out.h's put_each). The threads are
// started by the call and joined before it returns: nothing runs when no command does, and
// every thread has main's mask, SIGINT blocked.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace igds {

// The machine's cores, at most 8.
inline unsigned cores() {
  return std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
}

// The number of threads worth using for work on `items` numbers: 1 below a quarter of a million
// (a couple of milliseconds, where starting threads would cost as much), else cores().
inline unsigned threads_for(std::size_t items) {
  return items < (std::size_t(1) << 18) ? 1 : cores();
}

// Calls f(part) for every part in [0, parts), part 0 on the calling thread and each other on a
// thread of its own. If a thread cannot be started its part runs here; an exception thrown by
// any part is rethrown here once every part has finished.
template <class F>
void in_parallel(unsigned parts, const F& f) {
  if (parts <= 1) {
    if (parts == 1) f(0u);
    return;
  }
  std::vector<std::exception_ptr> errors(parts);
  auto run = [&f, &errors](unsigned part) {
    try {
      f(part);
    } catch (...) {
      errors[part] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(parts - 1);
  for (unsigned part = 1; part < parts; ++part) {
    try {
      pool.emplace_back(run, part);
    } catch (const std::system_error&) {
      run(part);
    }
  }
  run(0);
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

// Calls f(first, last) on `threads` contiguous slices of [0, count) at once (in_parallel).
template <class F>
void parallel_for(std::size_t count, unsigned threads, const F& f) {
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(count, 1)));
  in_parallel(threads, [&](unsigned t) { f(count * t / threads, count * (t + 1) / threads); });
}

}  // namespace igds
