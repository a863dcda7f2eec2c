// The reports of APL\360 (APL\360 User's Manual, appendix on error reports): the kind, and where
// the statement failed so that the session can print the statement with a caret under that point.
#pragma once

#include <cstddef>
#include <exception>
#include <string>
#include <string_view>

namespace igds::apl {

enum class ErrorKind {
  syntax,     // not a well-formed statement, or a function used with the wrong number of arguments
  value,      // a name without a value, or a function without a result used as an argument
  domain,     // an argument outside the function's domain (also overflow to infinity)
  length,     // arguments whose lengths do not agree
  rank,       // arguments whose ranks do not agree
  index,      // an index outside the array
  ws_full,    // a result larger than the workspace allows
  defn,       // a bad function definition or editor command
  depth,      // functions or parentheses nested too deeply
  interrupt,  // stopped: the host's interrupt, the end of input at ⎕ or ⍞, or the work budget
};

// The report's words: SYNTAX ERROR, ..., WS FULL, INTERRUPT.
std::string_view error_words(ErrorKind kind);

class Error : public std::exception {
 public:
  // A report of the kind; `words` replaces the standard words when given (a native function's
  // own report, e.g. INCORRECT ENTRY: ...).
  explicit Error(ErrorKind kind, std::string words = {});
  ErrorKind kind() const { return kind_; }
  const char* what() const noexcept override { return words_.c_str(); }

  // Where it happened: the statement as printed (e.g. "      1÷0" or "F[2]  X←1÷0") and the
  // column of the caret in that text. Set once, by the innermost statement that failed.
  bool located() const { return located_; }
  const std::string& statement() const { return statement_; }
  std::size_t caret() const { return caret_; }
  void locate(std::string statement, std::size_t caret);

  // The column (in characters, within the statement's text) of the failing token, when the
  // evaluator knows it; the statement is located later with it.
  bool has_column() const { return has_column_; }
  std::size_t column() const { return column_; }
  void set_column(std::size_t column);

 private:
  ErrorKind kind_;
  std::string words_;
  bool located_ = false, has_column_ = false;
  std::string statement_;
  std::size_t caret_ = 0, column_ = 0;
};

// Shorthands for the primitives.
[[noreturn]] void throw_error(ErrorKind kind);
[[noreturn]] inline void domain_error() {
  throw_error(ErrorKind::domain);
}
[[noreturn]] inline void length_error() {
  throw_error(ErrorKind::length);
}
[[noreturn]] inline void rank_error() {
  throw_error(ErrorKind::rank);
}
[[noreturn]] inline void index_error() {
  throw_error(ErrorKind::index);
}
[[noreturn]] inline void syntax_error() {
  throw_error(ErrorKind::syntax);
}

}  // namespace igds::apl
