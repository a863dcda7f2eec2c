#include "interp/apl/error.h"

namespace igds::apl {

std::string_view error_words(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::syntax:
      return "SYNTAX ERROR";
    case ErrorKind::value:
      return "VALUE ERROR";
    case ErrorKind::domain:
      return "DOMAIN ERROR";
    case ErrorKind::length:
      return "LENGTH ERROR";
    case ErrorKind::rank:
      return "RANK ERROR";
    case ErrorKind::index:
      return "INDEX ERROR";
    case ErrorKind::ws_full:
      return "WS FULL";
    case ErrorKind::defn:
      return "DEFN ERROR";
    case ErrorKind::depth:
      return "DEPTH ERROR";
    case ErrorKind::interrupt:
      return "INTERRUPT";
  }
  return "SYSTEM ERROR";
}

Error::Error(ErrorKind kind, std::string words)
    : kind_(kind), words_(words.empty() ? std::string(error_words(kind)) : std::move(words)) {}

void Error::locate(std::string statement, std::size_t caret) {
  if (located_) return;
  located_ = true;
  statement_ = std::move(statement);
  caret_ = caret;
}

void Error::set_column(std::size_t column) {
  if (has_column_) return;
  has_column_ = true;
  column_ = column;
}

void throw_error(ErrorKind kind) {
  throw Error(kind);
}

}  // namespace igds::apl
