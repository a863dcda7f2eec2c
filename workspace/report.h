// An IGDS error report. Commands throw it; only the interpreter loop catches it, prints what()
// word for word and returns to READY.
#pragma once

#include <stdexcept>
#include <string>

namespace igds {

struct Report : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The reports of the manual (spec igds.md section 2), word for word.
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

}  // namespace igds
