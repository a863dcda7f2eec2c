// Making a surface current: BUILD and CHANGE interpolate the new inputs (COONS then FIT) and
// only then replace the workspace's surface.
#pragma once

#include "commands/entries.h"
#include "workspace/kernels/surface.h"
#include "workspace/state.h"

namespace igds {

// COONS then FIT; a kernel's refusal becomes its report followed by `; THE SURFACE IS NOT
// CHANGED` (the surface in the workspace is kept).
Surface interpolate_surface(int nocur, int nostr, Density density, const Array& inppn,
                            const Array& inptg);

// Makes an interpolated surface the current one: the only change BUILD and CHANGE make to the
// workspace, once everything has been asked and computed. It counts as a new surface
// (Changes::replaced); CHANGE then says which parts of the inputs are new.
void make_current(Workspace& ws, int nocur, int nostr, Density density, Array inppn, Array inptg,
                  Surface surface);

}  // namespace igds
