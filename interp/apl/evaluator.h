// The evaluation of statements: names (the running functions' locals, the statement's pending
// assignments, the host's names, the session's variables, in that order), function calls,
// ⎕ and ⍞, and the primitives' dispatch. Used by AplSession; not part of the public interface.
#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "interp/apl/apl_session.h"
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

  // Immediate execution of one line: results displayed, errors reported, assignments made only
  // when the whole line succeeds.
  void run_line(std::string_view line);

  NameClass classify(const std::string& name) const;
  // A name's value as a statement sees it; nullopt when it has none.
  std::optional<Value> lookup(const std::string& name) const;
  // Assigns a variable: a running function's local, else kept aside until the line completes
  // (made at once when no line is running).
  void set_variable(const std::string& name, Value value);
  bool is_variable(const std::string& name) const;
  bool running() const { return running_; }

  // Output through the host, after what ⍞← left pending on the line.
  void print(std::string_view line);
  // Prints a report: the words, the statement and a caret; `typed` is the line as typed, for a
  // report not located in a function's line.
  void report(const Error& e, std::string_view typed);

  Host& host;
  Context ctx;
  std::map<std::string, Value> globals;
  std::map<std::string, std::shared_ptr<const DefinedFunction>> functions;
  std::map<std::string, NativeEntry> natives;
  AplSession::Next requested = AplSession::Next::stay;
  std::atomic<bool> interrupted{false};

 private:
  struct Frame {
    std::shared_ptr<const DefinedFunction> function;
    std::vector<std::pair<std::string, std::optional<Value>>> locals;
    std::vector<std::pair<std::string, Value>> saved_system;  // localized ⎕IO ⎕PP ⎕CT ⎕RL
    std::size_t line = 0;
    std::optional<Value>* find(const std::string& name);
    const std::optional<Value>* find(const std::string& name) const;
  };
  struct Outcome {
    bool branch = false, naked = false;
    double target = 0;
  };
  struct Escape {};  // → alone, or → typed at ⎕: abandon the line
  class Deeper;
  class FrameGuard;

  Outcome run_statement(const Statement& statement);
  std::optional<Value> eval(const Node& node);
  std::optional<Value> eval_node(const Node& node);
  Value value_of(const Node& node);
  bool shy(const Node& node) const;
  std::optional<Value> call(const std::string& name, const Value* left, const Value* right);
  std::optional<Value> call_defined(const std::shared_ptr<const DefinedFunction>& f,
                                    const Value* left, const Value* right);
  std::optional<Value> apply_monadic(const FunctionNode& f, Value b, const Value* axis);
  std::optional<Value> apply_dyadic(const FunctionNode& f, Value a, Value b, const Value* axis);
  std::optional<Value> execute_text(const Value& text);
  Value quad_input();
  Value quote_input();
  void quote_output(const Value& v);
  void assign_to(const std::string& name, const Value& v);
  Value& slot(const std::string& name);
  Value system_variable(const std::string& name) const;
  void set_system_variable(const std::string& name, const Value& v);
  void commit();
  void flush();

  std::vector<Frame> frames_;
  std::vector<std::pair<std::string, Value>> staged_;
  bool running_ = false;
  int depth_ = 0;
  std::u32string pending_;  // what ⍞← put on the line, not yet ended
  bool execute_shy_ = false;
  Classifier classifier_;
};

}  // namespace igds::apl
