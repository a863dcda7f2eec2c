// Ctrl-C while igds computes (docs/interp.md, "Ctrl-C and Ctrl-D"). SIGINT is blocked in every
// thread of igds from the first line of main, so no thread is ever ended by it: it stays pending
// until the conversation reads it (interp/input.h, Interrupts). A long loop asks, between pieces
// of its work, whether one is waiting, and gives up by throwing Interrupted.
#pragma once

namespace igds {

// Thrown by check_interrupt. Neither an igds::Error nor a std::exception, so that no handler
// meant for reports takes it: only the conversation catches it (Interpreter::perform), and
// whatever the command was making is dropped on the way.
struct Interrupted {};

// Blocks SIGINT in the calling thread and so in every thread it starts afterwards (a new thread
// inherits its creator's mask). main calls it before anything else.
void block_interrupts() noexcept;

// True while a Ctrl-C waits to be read. One system call: ask between pieces of work of a
// millisecond or more, not for every point.
bool interrupt_pending() noexcept;

// Throws Interrupted when a Ctrl-C waits.
inline void check_interrupt() {
  if (interrupt_pending()) throw Interrupted{};
}

// Reads the Ctrl-C that waits, if one does (the conversation, once it has acted on it): true
// when there was one.
bool take_interrupt() noexcept;

}  // namespace igds
