#include "workspace/kernels/interrupt.h"

#include <doctest/doctest.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <thread>

namespace igds {

TEST_CASE("a Ctrl-C waits, blocked, until it is read; a thread started after sees it too") {
  block_interrupts();
  while (take_interrupt()) {
  }
  CHECK_FALSE(interrupt_pending());
  CHECK_NOTHROW(check_interrupt());
  REQUIRE(::kill(::getpid(), SIGINT) == 0);  // the process's signal, as a terminal sends it
  CHECK(interrupt_pending());
  bool seen_by_thread = false, blocked_in_thread = false;
  std::thread([&] {
    seen_by_thread = interrupt_pending();
    sigset_t mask;
    pthread_sigmask(SIG_BLOCK, nullptr, &mask);
    blocked_in_thread = sigismember(&mask, SIGINT) == 1;
  }).join();
  CHECK(seen_by_thread);
  CHECK(blocked_in_thread);
  CHECK_THROWS_AS(check_interrupt(), Interrupted);
  CHECK(take_interrupt());
  CHECK_FALSE(interrupt_pending());
  CHECK_FALSE(take_interrupt());
}

}  // namespace igds
