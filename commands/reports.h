// What the commands say when a kernel refuses data: the kernels say what is wrong with typed
// fields (workspace/kernels/data_error.h); the report's words are chosen here, once.
#pragma once

#include "workspace/error.h"
#include "workspace/kernels/data_error.h"

namespace igds {

// The report for a kernel's refusal, e.g. INCORRECT ENTRY: POINT 7 IS NOT A FINITE NUMBER.
Report worded(const DataError& e);

// The same, followed by what was kept: `...; THE SURFACE IS NOT CHANGED`.
Report worded(const DataError& e, std::string_view kept);

}  // namespace igds
