#include "workspace/kernels/interrupt.h"

#include <pthread.h>
#include <signal.h>

namespace igds {

void block_interrupts() noexcept {
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  pthread_sigmask(SIG_BLOCK, &interrupt, nullptr);
}

bool interrupt_pending() noexcept {
  sigset_t pending;
  sigemptyset(&pending);
  // The process's pending signals and this thread's: a Ctrl-C is the process's.
  return sigpending(&pending) == 0 && sigismember(&pending, SIGINT) == 1;
}

bool take_interrupt() noexcept {
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  const timespec now{0, 0};
  return sigtimedwait(&interrupt, nullptr, &now) == SIGINT;
}

}  // namespace igds
