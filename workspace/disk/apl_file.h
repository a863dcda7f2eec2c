// END APL's own workspace on the disk (docs/disk.md): the user's functions and variables, in the
// session file (a section of BINSAVE.IGDSCONT) and in NAME.IGDSAPLW, which )SAVE writes beside
// NAME.IGDSDATA. One encoding for both; a file read is trusted for nothing: every count is
// checked against the bytes left before it sizes anything, every name must be an APL name, every
// number finite, every character a Unicode code point.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "workspace/disk/disk.h"
#include "workspace/disk/frame.h"
#include "workspace/state.h"

namespace igds::disk {

inline constexpr std::string_view apl_workspace_type = "IGDSAPLW";

// The functions: their count, then each its number of lines and the lines (length, bytes).
void write_functions(Writer& w, const std::vector<std::vector<std::string>>& functions);
std::vector<std::vector<std::string>> read_functions(Reader& r);

// The variables: their count, then each its name, kind (0 numbers, 1 characters), rank, shape
// and elements (f64 or u32 each).
void write_variables(Writer& w, const std::vector<AplVariable>& variables);
std::vector<AplVariable> read_variables(Reader& r);

// The bytes write_variables takes for one variable (the session keeps at most
// max_session_apl_bytes of them).
std::size_t stored_bytes(std::size_t name_bytes, std::size_t rank, std::size_t elements,
                         bool characters);

// What NAME.IGDSAPLW holds: whether )SAVE wrote the surface in NAME.IGDSDATA with it (when it
// did not, a NAME.IGDSDATA there is of another time and )LOAD leaves it), the functions and the
// variables.
struct AplWorkspace {
  bool surface = false;
  std::vector<std::vector<std::string>> functions;
  std::vector<AplVariable> variables;
};
// )SAVE: NAME.IGDSAPLW, replacing a file of that name (written whole or not at all: temporary,
// fsync, rename; never through a link). Throws Report CANNOT WRITE NAME.IGDSAPLW (REASON); `kept`.
void save_apl_workspace(const Disk& disk, std::string_view name, const AplWorkspace& ws,
                        std::string_view kept = "NOT SAVED");
// )LOAD and )COPY: what NAME.IGDSAPLW holds. Throws Report FILE NOT FOUND, CANNOT READ ..., or
// FILE DAMAGED: NAME.IGDSAPLW (REASON); `kept` (NOTHING LOADED, NOTHING COPIED).
AplWorkspace load_apl_workspace(const Disk& disk, std::string_view name,
                                std::string_view kept = "NOTHING LOADED");

}  // namespace igds::disk
