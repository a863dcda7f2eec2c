// The evaluation of statements: a machine that runs compiled statements (code.h) on a stack of
// values, with a stack of frames that is APL\360's state indicator. A typed line is a frame; a
// call of a defined function pushes one; ⍎ and ⎕ input push one for the text they run. A frame
// that fails is reported and, when it is a defined function's, stays on the stack suspended:
// the six-blank prompt comes back with its local names visible, →N resumes it at line N, → alone
// clears it (docs/apl.md, "The state indicator"). Used by AplSession; not part of the public
// interface.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "interp/apl/apl_session.h"
#include "interp/apl/code.h"
#include "interp/apl/context.h"
#include "interp/apl/function.h"
#include "interp/apl/parser.h"
#include "interp/apl/value.h"

namespace igds::apl {

struct NativeEntry {
  int valence = 0;
  AplSession::Native function;
  std::string help;
};

class Evaluator {
 public:
  explicit Evaluator(Host& host);

  // A line typed at the six-blank prompt: run until it completes or a function is suspended.
  void run_line(std::string_view line);

  // --- names ---
  // A name's class as a statement typed now sees it (locals of suspended functions included).
  NameClass classify(const std::string& name) const;
  // A name's value as a statement typed now sees it; nullopt when it has none.
  std::optional<Value> lookup(const std::string& name) const;
  // Assigns as a statement typed now would: a local of a suspended function, the host's name or
  // the session's variable. SYNTAX ERROR for a function's name.
  void set_variable(const std::string& name, Value value);
  // The session's own variable (not a local, not the host's).
  bool is_global_variable(const std::string& name) const;
  bool is_variable(const std::string& name) const;

  // The session's global variables, defined functions and natives, by name.
  std::vector<std::pair<std::string, Value>> globals() const;
  // Changes with every assignment or erasure of a global variable.
  std::uint64_t global_changes() const { return global_changes_; }
  // The global variables assigned or erased since global_changes() was `version`, by name, each
  // with its value (none: erased).
  std::vector<std::pair<std::string, std::optional<Value>>> globals_changed(
      std::uint64_t version) const;
  std::vector<std::string> function_names(bool natives) const;
  std::shared_ptr<const DefinedFunction> function(const std::string& name) const;
  const NativeEntry* native(const std::string& name) const;
  // Defines (or replaces) a function; DEFN ERROR when it is in use in a way that forbids it (a
  // pendent function, or a suspended one whose header changes).
  void define(DefinedFunction f);
  void define_native(const std::string& name, NativeEntry entry);
  // Erases a global variable or a defined function; false when there was none.
  bool erase(const std::string& name);
  // )CLEAR: no variables, no defined functions, the state indicator empty, system variables as
  // in a clear workspace (natives stay).
  void clear();

  // --- the state indicator ---
  // )SI: one line per function on the stack, the latest first, `F[3] *` when suspended.
  std::vector<std::string> state_indicator() const;
  // )SIC: everything on the stack abandoned.
  void clear_state_indicator();
  // True while a function waits on the state indicator for a function it called (pendent):
  // it cannot be edited.
  bool pendent(const std::string& name) const;

  // Output through the host, after what ⍞← left pending on the line.
  void print(std::string_view line);
  // The lines of a value at ⎕PW (continuation lines indented six blanks).
  void show(const Value& v);

  Host& host;
  Context ctx;
  AplSession::Next requested = AplSession::Next::stay;

 private:
  struct Symbol {
    std::string name;
    std::uint64_t changed = 0;  // global_changes_ when its value was last assigned or erased
    bool owned = false;         // the host's
    std::optional<Value> value;
    std::shared_ptr<const DefinedFunction> function;
    std::optional<NativeEntry> native;
  };
  struct Frame {
    enum class Kind : std::uint8_t { immediate, function, execute, quad };
    Kind kind = Kind::immediate;
    bool suspended = false;
    bool needs_value = false;       // the caller wants a result (VALUE ERROR without one)
    bool shadows = false;           // a local name is also a function's name
    bool executed_shy = false;      // what the last ⍎ of this frame ran was an assignment
    std::uint32_t call_column = 0;  // the caller's call, for that VALUE ERROR
    std::shared_ptr<const DefinedFunction> function;
    const Code* code = nullptr;         // the statement running
    std::shared_ptr<const Code> owned;  // its owner, unless the function's lines keep it
    std::size_t pc = 0;
    std::size_t line = 0;  // a function's: 1, 2, ...
    std::size_t base = 0;  // its first value on the stack
    std::vector<std::optional<Value>> slots;
    Value scratch{0.0};  // a dyadic's result for the →A/B that follows (code.h, Operand)
    std::vector<std::pair<SystemName, double>> saved;  // localized system variables
    std::string text;  // a typed, executed or ⎕ line, as reports show it
  };
  // → alone: the frames of the line typed at the prompt abandoned, and, when → was that line,
  // the suspension it was typed at.
  struct Escape {
    bool at_prompt = false;
  };

  std::uint32_t symbol(const std::string& name);
  const Symbol* find_symbol(const std::string& name) const;
  std::optional<Value>* local_slot(std::uint32_t id);
  const std::optional<Value>* local_slot(std::uint32_t id) const;
  Value load(std::uint32_t id) const;
  void store(std::uint32_t id, Value v);
  void index_store(std::uint32_t id, const Instr& in);
  NameClass class_of(std::uint32_t id) const;
  NameClass static_class(const std::string& name) const;
  void definitions_changed();

  std::shared_ptr<const Code> compile_text(std::u32string_view text, bool& branch_or_empty);
  const Code* function_line(Frame& f);
  void push_frame(Frame f);
  void pop_frame();
  void run();
  void step();
  void start_statement(Frame& f);
  void end_statement(const Instr& in);
  // A dyadic primitive not done on the spot: A, and B when it was not on the stack (with the axis,
  // it is below it).
  Value dyadic_primitive(const Instr& in, Value a, std::optional<Value> right);
  void branch(Frame& f, const Value& target);
  void return_from_function();
  void call(std::uint32_t id, const Instr& in, int valence);
  void call_native(const NativeEntry& native, const Instr& in, const Value* left,
                   const Value* right);
  void push_result(std::optional<Value> v, const Instr& in);
  void execute_text(const Instr& in);
  void quad_input(const Instr& in);
  void quote_output(const Value& v);
  void fail(Error e);
  void escape(bool at_prompt);
  void report(const Error& e, std::string_view typed);
  void flush();
  Value pop();
  // An argument read straight from a slot or a constant (code.h, Operand).
  const Value& argument(const Frame& f, const Operand& o) const;

  Value system_variable(SystemName s) const;
  void set_system_variable(SystemName s, const Value& v);
  Value system_function(SystemName s, const Value& b);
  void restore_system(const Frame& f);

  std::vector<Symbol> symbols_;
  std::unordered_map<std::string, std::uint32_t> ids_;
  std::vector<Frame> frames_;
  std::vector<Value> stack_;
  std::uint64_t generation_ = 1;  // changes with every definition of a function
  int shadowing_ = 0;             // frames whose locals hide a function's name
  std::u32string pending_;        // what ⍞← put on the line, not yet ended
  std::uint64_t started_ = 0;     // the session's start, for ⎕AI (milliseconds)
  std::uint64_t global_changes_ = 0;
  void changed(Symbol& s) { s.changed = ++global_changes_; }
};

}  // namespace igds::apl
