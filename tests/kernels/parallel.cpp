// Splitting work between threads (parallel.h) and outputs written into the memory they had
// (Array::reshape_for_output).
#include "workspace/kernels/parallel.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

#include "workspace/kernels/array.h"

using namespace igds;

TEST_CASE("parallel_for covers every index exactly once") {
  for (std::size_t count : {0u, 1u, 2u, 3u, 7u, 100u, 1001u}) {
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
      std::vector<std::atomic<int>> seen(count);
      parallel_for(count, threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) ++seen[k];
      });
      CAPTURE(count);
      CAPTURE(threads);
      for (auto& s : seen) CHECK(s.load() == 1);
    }
  }
}

TEST_CASE("an exception in any slice reaches the caller after all threads have finished") {
  std::atomic<int> finished{0};
  auto throwing = [&](std::size_t first, std::size_t) {
    if (first > 0) throw std::runtime_error("slice failed");
    ++finished;
  };
  CHECK_THROWS_WITH_AS(parallel_for(10, 2, throwing), "slice failed", std::runtime_error);
  CHECK(finished.load() == 1);
  CHECK_THROWS_AS(parallel_for(10, 1, [](std::size_t, std::size_t) { throw std::bad_alloc(); }),
                  std::bad_alloc);
}

TEST_CASE("in_parallel: part 0 here, every other part on a thread of its own, each once") {
  const auto here = std::this_thread::get_id();
  for (unsigned parts : {0u, 1u, 2u, 5u}) {
    std::vector<std::thread::id> on(parts);
    std::vector<std::atomic<int>> runs(parts);
    in_parallel(parts, [&](unsigned part) {
      on[part] = std::this_thread::get_id();
      ++runs[part];
    });
    for (unsigned part = 0; part < parts; ++part) {
      CHECK(runs[part].load() == 1);
      CHECK((on[part] == here) == (part == 0));
    }
  }
}

TEST_CASE("threads_for: one thread below a quarter of a million numbers") {
  CHECK(threads_for(10) == 1);
  CHECK(threads_for((std::size_t(1) << 18) - 1) == 1);
  CHECK(threads_for(std::size_t(1) << 24) >= 1);
  CHECK(threads_for(std::size_t(1) << 24) <= 8);
}

TEST_CASE("an array of a shape is zeros; an output's numbers are the ones written") {
  // Memory freed with other numbers in it is what the allocator hands out next.
  for (int round = 0; round < 2; ++round) {
    {
      Array used({4096});
      std::fill(used.ravel.begin(), used.ravel.end(), 7.0);
    }
    Array a({4096});
    CHECK(std::count(a.ravel.begin(), a.ravel.end(), 0.0) == 4096);
  }
  Array out;
  out.reshape_for_output({4096});
  std::iota(out.ravel.begin(), out.ravel.end(), 1.0);
  CHECK(out.ravel[4095] == 4096.0);
  out.reshape_for_output({3000});  // the memory is kept, the numbers before stay
  CHECK(out.ravel[2999] == 3000.0);
}

TEST_CASE("reshape_for_output keeps memory of a fitting size and replaces the rest") {
  Array a({1000, 3});
  const double* memory = a.data();
  a.reshape_for_output({600, 3});
  CHECK(a.data() == memory);
  CHECK(a.shape == std::vector<std::size_t>{600, 3});
  CHECK(a.size() == 1800);
  a.reshape_for_output({1000, 3});
  CHECK(a.data() == memory);
  CHECK(a.size() == 3000);
  a.reshape_for_output({100, 3});  // far smaller: the memory is given back
  CHECK(a.size() == 300);
  CHECK(a.ravel.capacity() < 1000);
  a.reshape_for_output({5000, 3});  // larger: new memory
  CHECK(a.size() == 15000);
}
