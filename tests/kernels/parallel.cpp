// Splitting work between threads (parallel.h) and outputs written into the memory they had
// (Array::reshape_for_output).
#include "workspace/kernels/parallel.h"

#include <doctest/doctest.h>

#include <atomic>
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

TEST_CASE("both: two tasks at once on two threads, or in turn on this one") {
  const auto here = std::this_thread::get_id();
  for (bool together : {false, true}) {
    std::vector<int> order;
    std::thread::id first_on, second_on;
    std::atomic<int> done{0};
    both(
        together,
        [&] {
          first_on = std::this_thread::get_id();
          ++done;
          if (!together) order.push_back(1);
        },
        [&] {
          second_on = std::this_thread::get_id();
          ++done;
          if (!together) order.push_back(2);
        });
    CHECK(done.load() == 2);
    CHECK(first_on == here);
    CHECK((second_on == here) == !together);
    if (!together) CHECK(order == std::vector<int>{1, 2});
  }
  std::atomic<bool> first_ran{false};
  CHECK_THROWS_WITH_AS(
      both(
          true, [&] { first_ran = true; }, [] { throw std::runtime_error("second failed"); }),
      "second failed", std::runtime_error);
  CHECK(first_ran.load());
}

TEST_CASE("halfway: the items whose weights reach half of all") {
  const std::vector<std::size_t> w{5, 1, 1, 1, 1, 1};  // 10 in all
  auto weight = [&](std::size_t k) { return w[k]; };
  CHECK(halfway(w.size(), weight) == 1);  // 5 of 10
  const std::vector<std::size_t> even{1, 1, 1, 1};
  CHECK(halfway(even.size(), [&](std::size_t k) { return even[k]; }) == 2);
  const std::vector<std::size_t> late{1, 1, 1, 7};
  CHECK(halfway(late.size(), [&](std::size_t k) { return late[k]; }) == 4);
  CHECK(halfway(0, weight) == 0);
}

TEST_CASE("threads_for: one thread below a quarter of a million numbers") {
  CHECK(threads_for(10) == 1);
  CHECK(threads_for((std::size_t(1) << 18) - 1) == 1);
  CHECK(threads_for(std::size_t(1) << 24) >= 1);
  CHECK(threads_for(std::size_t(1) << 24) <= 8);
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
