// What the primitives need besides their arguments: the system variables (⎕IO ⎕PP ⎕CT ⎕RL ⎕PW),
// the limits that keep a statement from exhausting the machine, and the work done so far, which
// says when to look for a Ctrl-C.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "interp/apl/error.h"
#include "interp/apl/value.h"

namespace igds::apl {

struct Limits {
  // The largest array, in elements (WS FULL beyond): 2^28 doubles are 2 GiB.
  std::size_t max_elements = std::size_t{1} << 28;
  // Work units (elements produced, statements executed, multiplications of an inner product) one
  // typed line may spend before it is interrupted; 0 for no limit.
  std::uint64_t max_work = 0;
  // Parentheses nested in a statement, and frames on the state indicator (function calls, ⍎, ⎕
  // input): DEPTH ERROR beyond.
  int max_depth = 1000;
};

// Ctrl-C: true, and the interrupt read (so that it is acted on once), when one waits
// (workspace/kernels/interrupt.h: SIGINT stays pending, blocked, until read).
bool take_interrupt();

struct Context {
  int io = 1;                // ⎕IO, 1 or 0
  int pp = 10;               // ⎕PP, significant digits displayed
  double ct = 1e-13;         // ⎕CT, the relative comparison tolerance
  std::uint32_t rl = 16807;  // ⎕RL, the random link (APL\360's 7*5)
  int pw = 80;               // ⎕PW, the width of a line of output ()WIDTH)
  Limits limits;
  std::uint64_t work = 0;  // spent on the current line
  // Ctrl-C is looked for each time this much work is done: a system call every few thousand
  // statements or few hundred thousand elements, never per element.
  static constexpr std::uint64_t poll_interval = std::uint64_t{1} << 18;
  std::uint64_t next_poll = poll_interval;

  // A new line: its work counted from nothing.
  void start_line() {
    work = 0;
    next_poll = 0;
  }
  // Counts `units` of work; INTERRUPT when the line's budget is spent or Ctrl-C waits.
  void charge(std::uint64_t units) {
    work += units;
    if (work >= next_poll) poll();
  }
  void poll() {
    if (limits.max_work != 0 && work > limits.max_work) throw Error(ErrorKind::interrupt);
    next_poll = work + poll_interval;
    if (limits.max_work != 0) next_poll = std::min(next_poll, limits.max_work + 1);
    if (take_interrupt()) throw Error(ErrorKind::interrupt);
  }

  // The element count of a shape, WS FULL when it exceeds the limit (or overflows).
  std::size_t checked_count(const Shape& shape) const {
    std::size_t n = 1;
    bool zero = false;
    for (auto d : shape) zero = zero || d == 0;
    if (zero) return 0;
    for (auto d : shape) {
      if (d > limits.max_elements || n > limits.max_elements / d) throw Error(ErrorKind::ws_full);
      n *= d;
    }
    return n;
  }

  // New results: checked, charged, uninitialised.
  Value new_numbers(Shape shape) {
    charge(checked_count(shape));
    return Value::uninitialised_numbers(std::move(shape));
  }
  Value new_characters(Shape shape) {
    charge(checked_count(shape));
    return Value::uninitialised_characters(std::move(shape));
  }
  Value new_like(bool characters, Shape shape) {
    return characters ? new_characters(std::move(shape)) : new_numbers(std::move(shape));
  }

  // The next number of the random sequence in (0, 1): the Lehmer generator of APL\360,
  // ⎕RL ← (7*5) × ⎕RL modulo (2*31)-1.
  double random() {
    rl = static_cast<std::uint32_t>((std::uint64_t{16807} * rl) % 2147483647u);
    return rl / 2147483647.0;
  }
};

// Tolerant equality (APL2 Language Reference, "comparison tolerance"): |A-B| ≤ ⎕CT × (|A|⌈|B|).
inline bool tolerant_equal(double a, double b, double ct) {
  if (a == b) return true;
  return std::fabs(a - b) <= ct * std::max(std::fabs(a), std::fabs(b));  // no NaN in APL
}

// Tolerant floor (APL2 Language Reference, "floor"): the nearest integer N, less one when N
// exceeds B by more than the tolerance.
inline double tolerant_floor(double b, double ct) {
  double n = std::floor(b + 0.5);
  if (n - b > ct * std::max(1.0, std::fabs(b))) n -= 1;
  return n;
}

// An integer within the tolerance (a near-integer is accepted where APL wants an integer).
inline bool near_integer(double x, double ct = 1e-13) {
  return std::fabs(x - std::round(x)) <= ct * std::max(1.0, std::fabs(x));
}

// The integer a number stands for; DOMAIN ERROR when it is not one (or is too large).
inline std::int64_t integer_of(double x) {
  if (!near_integer(x) || std::fabs(x) > 9.0e15) domain_error();
  return static_cast<std::int64_t>(std::llround(x));
}

// A non-negative integer (a length or a count).
inline std::size_t count_of(double x) {
  std::int64_t n = integer_of(x);
  if (n < 0) domain_error();
  return static_cast<std::size_t>(n);
}

// Boolean arguments (∧ ∨ ⍲ ⍱ ~, compress, expand): 0 or 1 only.
inline bool boolean_of(double x) {
  if (x == 0) return false;
  if (x == 1) return true;
  domain_error();
}

}  // namespace igds::apl
