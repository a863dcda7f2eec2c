// Making a surface current: BUILD, CHANGE and FIT interpolate the new inputs (COONS then FIT)
// and only then replace the workspace's surface.
#pragma once

#include "commands/entries.h"
#include "workspace/kernels/surface.h"
#include "workspace/state.h"

namespace igds {

// How a surface's patches are made besides its inputs: STATUS[3] and STATUS[4] (state.h).
struct SurfaceModes {
  bool marks_twists = false;   // CHANGE TWISTS MARKS: Marks's twists in PATCHES
  bool auto_tangents = false;  // the border tangents were set by AUTO
};

// COONS then FIT; a kernel's refusal becomes its report followed by `; THE SURFACE IS NOT
// CHANGED` (the surface in the workspace is kept).
Surface interpolate_surface(int nocur, int nostr, Density density, const Array& inppn,
                            const Array& inptg, bool marks_twists = false);

// Makes an interpolated surface the current one: the only change BUILD and CHANGE make to the
// workspace, once everything has been asked and computed. It counts as a new surface
// (Changes::replaced; `derived` false when PATCHES are not the interpolation of the inputs, as
// FIT's); CHANGE then says which parts of the inputs are new.
void make_current(Workspace& ws, int nocur, int nostr, Density density, Array inppn, Array inptg,
                  Surface surface, SurfaceModes modes = {}, bool derived = true);

}  // namespace igds
