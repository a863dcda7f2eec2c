// The errors igds reports, under one base (std::exception). Each carries the line the user sees
// (the manual's words first, then what is wrong) and its reason alone. Commands throw them; the
// interpreter's loop catches them at one place, prints what() word for word and returns to READY.
#pragma once

#include <exception>
#include <string>
#include <string_view>

namespace igds {

// The reports of the manual (docs/interp.md, "The dialogue"), word for word.
namespace reports {
inline constexpr const char* incorrect_command = "INCORRECT COMMAND OR PARAMETERS";
inline constexpr const char* incorrect_choice = "INCORRECT CHOICE OF PARAMETERS";
inline constexpr const char* incorrect_entry = "INCORRECT ENTRY";
inline constexpr const char* incorrect_parameter = "INCORRECT PARAMETER";
inline constexpr const char* input_not_found = "INPUT NOT FOUND";
inline constexpr const char* surface_not_found = "SURFACE NOT FOUND";
inline constexpr const char* image_not_found = "IMAGE NOT FOUND";
inline constexpr const char* file_not_found = "FILE NOT FOUND";
}  // namespace reports

class Error : public std::exception {
 public:
  // `words` (a manual report such as INCORRECT ENTRY, or a report of the same style) and, when
  // there is one, the reason, joined by a colon: INCORRECT ENTRY: POINT 6 IS NOT A CORNER.
  explicit Error(std::string_view words, std::string_view reason = {});
  const char* what() const noexcept override { return line_.c_str(); }
  const std::string& line() const { return line_; }
  const std::string& reason() const { return reason_; }

 protected:
  // A line composed by a subclass (e.g. CANNOT WRITE X (REASON); NO FILE CHANGED).
  struct Composed {};
  Error(Composed, std::string line, std::string reason)
      : line_(std::move(line)), reason_(std::move(reason)) {}

 private:
  std::string line_, reason_;
};

// A report that ends the command: the workspace is as before it.
struct Report : Error {
  using Error::Error;
};

// A data entry that is malformed or out of range: INCORRECT ENTRY, the entry is ignored and the
// next one awaited (the command goes on).
struct EntryError : Error {
  explicit EntryError(std::string_view reason = {}) : Error(reports::incorrect_entry, reason) {}
};

// A bad parameter (a name, a projection parameter): INCORRECT PARAMETER.
struct ParameterError : Report {
  explicit ParameterError(std::string_view reason = {})
      : Report(reports::incorrect_parameter, reason) {}
};

// --strict: the first error report in a command file stops the command files (exit status 3).
struct StrictStop : Error {
  StrictStop() : Error("STRICT STOP") {}
};

}  // namespace igds
