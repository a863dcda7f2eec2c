// Splitting work between threads and preparing large outputs (parallel.h, large_array.h).
#include "workspace/kernels/parallel.h"

#include <doctest/doctest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "workspace/kernels/large_array.h"

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

TEST_CASE("large_array gives a zero-filled array of the shape, small or large") {
  Array small = large_array({2, 3}, 2);
  CHECK(small == Array({2, 3}));
  Array large = large_array({1100, 1000, 3}, 2);  // 26 MB: prepared by two threads
  CHECK(large.shape == std::vector<std::size_t>{1100, 1000, 3});
  REQUIRE(large.size() == 3300000);
  bool all_zero = true;
  for (double v : large.ravel) all_zero = all_zero && v == 0;
  CHECK(all_zero);
  CHECK(threads_for(10) == 1);
}

TEST_CASE("reuse_for_output keeps memory of a fitting size and replaces the rest") {
  Array a({1000, 3});
  const double* memory = a.data();
  reuse_for_output(a, {600, 3}, 1);
  CHECK(a.data() == memory);
  CHECK(a.shape == std::vector<std::size_t>{600, 3});
  CHECK(a.size() == 1800);
  reuse_for_output(a, {1000, 3}, 1);
  CHECK(a.data() == memory);
  CHECK(a.size() == 3000);
  reuse_for_output(a, {100, 3}, 1);  // far smaller: the memory is given back
  CHECK(a.size() == 300);
  CHECK(a.ravel.capacity() < 1000);
  reuse_for_output(a, {5000, 3}, 1);  // larger: new memory
  CHECK(a.size() == 15000);
}
