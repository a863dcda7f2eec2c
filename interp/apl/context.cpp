#include "interp/apl/context.h"

#include <signal.h>

#include "workspace/kernels/interrupt.h"

namespace igds::apl {

// The session reads the Ctrl-C it acts on: left pending, it would stop every later statement
// where nobody reads it (command files), and the conversation would see it again at its prompt.
bool take_interrupt() {
  if (!igds::interrupt_pending()) return false;
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  const timespec now{0, 0};
  sigtimedwait(&interrupt, nullptr, &now);
  return true;
}

}  // namespace igds::apl
