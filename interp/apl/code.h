// A statement compiled once into the order APL evaluates it (right to left), for the evaluator's
// machine (evaluator.h): a list of instructions working on a stack of values. A defined function's
// line is compiled the first time it runs and kept with the function, so that a loop reads and
// parses each line once, not at every pass.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "interp/apl/parser.h"
#include "interp/apl/value.h"

namespace igds::apl {

struct DyadicLoops;

enum class Op : std::uint8_t {
  constant,            // push constants[a]
  local,               // push the running function's slot a
  name,                // push the value of symbol a, looked up through the running functions
  niladic,             // call function symbol a
  system_variable,     // push ⎕IO, ⎕PP, ... (SystemName a)
  quad_input,          // ⎕: evaluated input
  quote_input,         // ⍞: character input
  monadic,             // primitive a of B (axis below B when flagged)
  dyadic,              // A primitive a B
  execute,             // ⍎B
  reduce,              // a/B, a⌿B (b is the operator)
  scan,                // a\B, a⍀B
  outer,               // A ∘.a B
  inner,               // A a.b B
  call_monadic,        // function symbol a of B
  call_dyadic,         // A function symbol a B
  system_function,     // ⎕EX B, ⎕NC B, ... (SystemName a)
  index,               // B[...]: `count` indices, which positions given: index_lists[a]
  assign_local,        // slot a ← top (the value stays)
  assign_name,         // symbol a ← top
  assign_system,       // ⎕IO ← top, ... (SystemName a)
  assign_quad,         // ⎕ ← top: displayed
  assign_quote,        // ⍞ ← top: displayed, the line left open
  index_assign_local,  // slot a [indices] ← value below them
  index_assign_name,   // symbol a [indices] ← value below them
  branch,              // → top
  branch_compress,     // → A/B, A and B as for dyadic (the loops' idiom, no array made for it)
  naked_branch,        // → alone
  end,                 // the end of the statement: its value shown when flagged
};

enum InstrFlag : std::uint8_t {
  has_axis = 1,     // an axis [k] was pushed after the right argument
  needs_value = 2,  // a call whose result is an argument: VALUE ERROR when it has none
  shows = 4,        // end: the statement's value is displayed
  shy_execute = 8,  // end: the statement is ⍎B, shown unless what ⍎ ran was an assignment
  first_axis = 16,  // reduce, scan: ⌿ ⍀
  scalar = 32,      // monadic, dyadic: a scalar function (dyadic: `loops` are its loops)
  ends = 64,        // assign_local, dyadic into a slot: the statement ends with it (not shown)
};

// Where an argument of dyadic and branch_compress comes from: the stack, or straight from a
// slot of the running function or a constant (no copy of it pushed), read when the instruction
// runs.
struct Operand {
  // scratch: the frame's own place for one value, from a dyadic's result to →A/B's A.
  enum From : std::uint8_t { stack, local, constant, scratch };
  From from = stack;
  std::uint32_t index = 0;
  std::uint32_t column = 0;  // for VALUE ERROR at an unset local
};

struct Instr {
  Op op = Op::end;
  std::uint8_t flags = 0;
  std::uint16_t count = 0;  // index: the number of positions
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  std::uint32_t column = 0;  // of the token, for the caret under a failure
  const DyadicLoops* loops = nullptr;
  Operand left, right;
  // dyadic: where the result goes: the stack, or (with `ends`) a slot, the statement `Z←A f B`
  // ending there.
  Operand result;
};

// The system names igds's APL has: variables, then functions.
enum class SystemName : std::uint8_t {
  io,
  pp,
  ct,
  rl,
  pw,
  lc,
  ts,
  ai,
  av,  // variables (⎕LC ⎕TS ⎕AI ⎕AV only read)
  ex,
  nc,
  fx,
  cr,  // monadic functions
};
// The system name of ⎕IO etc. (the whole name, quad included), or false.
bool system_name(const std::string& name, SystemName& out);
bool is_system_function(SystemName s);
// The name with its quad, for reports and listings.
std::string system_name_text(SystemName s);

struct Code {
  std::vector<Instr> instrs;
  std::vector<Value> constants;
  std::vector<std::vector<bool>> index_lists;  // per index: true where an index is given
  bool branch = false;                         // a branch statement (→): never shown
};

// How compile names a name: a slot of the running function (a label when `label`), or a symbol
// of the session.
struct NameRef {
  bool local = false, label = false;
  std::uint32_t index = 0;
};
using Resolver = std::function<NameRef(const std::string& name)>;

// The instructions of a parsed statement. SYNTAX ERROR (with its column) for an unknown system
// name or an assignment to a label.
Code compile(const Statement& statement, const Resolver& resolve);

}  // namespace igds::apl
