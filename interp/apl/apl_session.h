// An APL\360 session: lines typed at the six-blank prompt are statements, system commands
// ()VARS ...) or lines of the ∇ editor. The session keeps its own variables and defined
// functions; the Host around it prints, reads input, and may own names of its own (igds's
// workspace variables) and give native functions (the manual's FIT, COONS, ...).
//
// As in APL\360, an assignment is made when it is reached: a statement that fails keeps what it
// assigned before the failure. A failure prints the report, the statement and a caret under the
// point where it failed; a defined function that fails (or is interrupted) stays suspended on
// the state indicator, its local names visible, until →N resumes it or → clears it
// (docs/apl.md).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "interp/apl/context.h"
#include "interp/apl/error.h"
#include "interp/apl/value.h"

namespace igds::apl {

class Host {
 public:
  virtual ~Host() = default;
  // One line of output (UTF-8, no line end).
  virtual void print(std::string_view line) = 0;
  // One line of input for ⎕ (prompt: six blanks, after a line ⎕:) and ⍞ (prompt: what ⍞←
  // left on the line); nullopt at the end of the input (the statement is interrupted).
  virtual std::optional<std::string> read_line(std::string_view prompt) = 0;

  // Names the host owns (igds's NOCUR, INPPN, ...): they are read and assigned through it.
  virtual bool owns(std::string_view /*name*/) const { return false; }
  // The value of an owned name; nullopt when it has none (VALUE ERROR).
  virtual std::optional<Value> get(std::string_view /*name*/) { return std::nullopt; }
  // Called when an owned name is assigned: throw an Error (e.g. DOMAIN ERROR) to refuse the
  // value, which fails the statement there.
  virtual void check(std::string_view /*name*/, const Value& /*value*/) {}
  // Then the owned name takes the value.
  virtual void set(std::string_view /*name*/, const Value& /*value*/) {}
  // The owned names that have a value, for )VARS.
  virtual std::vector<std::string> variable_names() const { return {}; }
  // What )VARS and )FNS call the host's names and functions, listed after the session's own
  // (e.g. IGDS); empty: listed without a heading.
  virtual std::string heading() const { return {}; }

  // )SAVE NAME, )LOAD NAME, )COPY NAME [names]: the host maps them onto its files; the lines to
  // print.
  virtual std::vector<std::string> save_workspace(std::string_view /*name*/) {
    return {"INCORRECT COMMAND"};
  }
  virtual std::vector<std::string> load_workspace(std::string_view /*name*/) {
    return {"INCORRECT COMMAND"};
  }
  virtual std::vector<std::string> copy_workspace(std::string_view /*name*/,
                                                  const std::vector<std::string>& /*names*/) {
    return {"INCORRECT COMMAND"};
  }
};

class AplSession {
 public:
  explicit AplSession(Host& host);
  ~AplSession();
  AplSession(const AplSession&) = delete;
  AplSession& operator=(const AplSession&) = delete;

  // Where the dialogue goes after a line: on in APL, back to the IGDS conversation (START),
  // or out of igds ()OFF).
  enum class Next { stay, start, off };

  // One typed line: a statement, a system command, or a line of the ∇ editor. Output and
  // error reports go to the host.
  Next execute(std::string_view line);
  // Six blanks, or "[n] " while a function is being defined or edited.
  std::string prompt() const;
  bool defining() const;

  // A function given by the host, niladic (valence 0), monadic (1) or dyadic (2). It receives
  // null for an absent argument, returns nullopt for no result, and reports with Error (any
  // other std::exception is reported by its what()). Replaces a function of that name;
  // `help` is one line for the host's HELP. START is predefined as a niladic function that
  // requests Next::start.
  using Native = std::function<std::optional<Value>(const Value* left, const Value* right)>;
  void define_native(std::string name, int valence, Native function, std::string help = {});
  std::string function_help(std::string_view name) const;

  // The functions, defined and native, in alphabetical order ()FNS).
  std::vector<std::string> function_names() const;
  // The defined functions' sources (header, then lines), in alphabetical order of their names,
  // to be kept by the host and defined again later.
  std::vector<std::vector<std::string>> defined_functions() const;
  // Defines (or replaces) a function from its source; DEFN ERROR when the source is bad or the
  // name is a variable or a native function.
  void define_function(const std::vector<std::string>& source);
  // The name a function's source defines; DEFN ERROR for a bad header.
  static std::string function_name(const std::vector<std::string>& source);

  // The session's own variables (not the host's), in alphabetical order, for )SAVE.
  std::vector<std::pair<std::string, Value>> variables() const;
  // A number that changes whenever one of those variables is assigned or erased, and those
  // assigned or erased since it was `version`, each with its value (none: erased).
  std::uint64_t variables_version() const;
  std::vector<std::pair<std::string, std::optional<Value>>> variables_changed(
      std::uint64_t version) const;
  // A variable's value as a statement would see it (inside a statement: with its pending
  // assignments, and the running functions' local names); nullopt when it has none.
  std::optional<Value> variable(std::string_view name) const;
  // Assigns a variable (inside a statement: kept aside with the statement's assignments).
  // SYNTAX ERROR when the name is a function's.
  void assign(std::string_view name, Value value);
  // )ERASE: false when there is no such variable or defined function of the session.
  bool erase(std::string_view name);
  // )CLEAR: no variables, no defined functions, an empty state indicator, the system variables
  // of a clear workspace (natives stay).
  void clear();
  // )SI: the functions on the state indicator, the latest first (`F[3] *` when suspended).
  std::vector<std::string> state_indicator() const;

  int index_origin() const;
  void set_index_origin(int origin);  // 0 or 1; DOMAIN ERROR otherwise
  int print_precision() const;
  void set_print_precision(int digits);  // 1 to 17; DOMAIN ERROR otherwise
  int print_width() const;
  void set_print_width(int width);  // ⎕PW, 30 to 254; DOMAIN ERROR otherwise

  // A native function asks where to go once the current line is done.
  void request(Next next);
  // Ctrl-C while a statement runs is a pending SIGINT (workspace/kernels/interrupt.h): the
  // session looks for one between statements and within long primitives, reads it, and reports
  // INTERRUPT where it stopped, suspending the function that ran.
  void set_limits(const Limits& limits);
  const Limits& limits() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace igds::apl
