// The memory made ready while igds waits for a line (Interpreter::prepare_memory,
// workspace/kernels/big_blocks.h): after each command, and as igds begins.
#include <doctest/doctest.h>

#include <chrono>
#include <thread>

#include "interp/interpreter.h"
#include "tests/support/process.h"
#include "tests/support/scripted.h"
#include "workspace/kernels/big_blocks.h"

namespace igds::test {

namespace {

// Waits (a minute at most, so that a slow machine still passes) until the blocks keep `bytes`.
bool kept_within_a_minute(std::size_t bytes) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (big_blocks::figures().kept < bytes) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

// What earlier tests left kept (APL ravels are large blocks), held while a test runs.
struct Hold {
  void* block;
  Hold()
      : block(big_blocks::figures().kept ? big_blocks::allocate(big_blocks::figures().kept)
                                         : nullptr) {}
  ~Hold() {
    if (block) big_blocks::release(block);
  }
};

}  // namespace

#ifdef __linux__
TEST_CASE("while igds waits for a line, memory for an image of its surface is made ready") {
  const Hold earlier;
  REQUIRE(big_blocks::figures().kept == 0);
  // 803 x 803 points: an image of 16 bytes a point.
  const std::size_t image = std::size_t{803} * 803 * 16;
  TempDir dir;
  Disk disk(dir.path());
  {
    Session session(disk);
    session.set_make_ahead_delay_for_testing(std::chrono::milliseconds(0));
    StringOutput out;
    ScriptedSource input(false, true);
    Terminal terminal(TermMode::none, {}, out);
    Interpreter interpreter(Options{}, disk, session, session.load(), terminal);
    terminal.use_input(&input);
    terminal.begin();
    // No surface: nothing wanted, however long igds waits (a wish would be met at once).
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    CHECK(big_blocks::figures().kept == 0);
    input.lines({"BUILD", "3 3", "1 0 0 0 10 0 2 20 0 0", "4 0 12 2 10 12 0 20 12 2",
                 "7 0 24 0 10 24 2 20 24 0", "", "AUTO", "", "400 400"});
    CHECK(interpreter.converse() == Interpreter::Outcome::input_ended);
    CHECK(kept_within_a_minute(image));
    CHECK(big_blocks::figures().kept < image + (2u << 20));  // no more than that
  }
  // At the next start, a moment after it begins: the size from NOCUR ... INTST, INTPN being
  // made again behind READY.
  const Hold first;
  REQUIRE(big_blocks::figures().kept == 0);
  Session session(disk);
  StringOutput out;
  Terminal terminal(TermMode::none, {}, out);
  Interpreter interpreter(Options{}, disk, session, session.load(true), terminal);
  CHECK(kept_within_a_minute(image));
}
#endif

}  // namespace igds::test
