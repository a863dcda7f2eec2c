// END APL (spec igds.md section 6): a small APL environment in which the workspace variables
// can be looked at. Prompted by six blanks, as APL did.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/kernels/array.h"
#include "workspace/state.h"

namespace igds {

inline constexpr std::string_view apl_prompt = "      ";

// A workspace variable by its name (any case): NOCUR NOSTR INTCU INTST INPPN INPTG PATCHES
// INTPN IMAGE DESIM TEMP1 DEST1 TEMP2 DEST2 STATUS. nullopt when there is no such variable or
// it has no value (no current image, no stored copy): VALUE ERROR, as for an unassigned name.
std::optional<Array> workspace_variable(const Workspace& ws, std::string_view name);

// The variables that have a value, in alphabetical order (as )VARS lists them).
std::vector<std::string> defined_variables(const Workspace& ws);

// An array as APL displays it: a scalar as a number, a vector on one line, a matrix as rows
// with the decimal points of each column aligned, higher ranks as matrices separated by blank
// lines (one more for each outer axis that moves on). An empty array is an empty line.
std::vector<std::string> apl_display(const Array& a);

// ⍴: the shape on one line (an empty line for a scalar).
std::string apl_shape(const Array& a);

// One line typed in the environment: what to print and where to go next.
enum class AplNext { stay, start, off };
struct AplReply {
  std::vector<std::string> lines;
  AplNext next = AplNext::stay;
};
AplReply apl_line(const Workspace& ws, std::string_view line);

}  // namespace igds
