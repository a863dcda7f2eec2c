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

// COONS then FIT, the patches not kept (Workspace::patches), or FIT alone from the workspace's own
// PATCHES when `refit_only` (the patches do not depend on the grid), into the memory of the
// workspace's INTPN, taken out of it when it is its interpolation (made again if need be): a new
// surface of about the same size writes no fresh pages, which on a large grid cost more than the
// interpolation. The kernels check everything first, and the result is checked to be finite;
// when either refuses, the workspace's arrays are as they were and the report is followed by
// `; THE SURFACE IS NOT CHANGED`.
Surface interpolate_surface(Workspace& ws, const SurfaceInput& input, bool refit_only = false);

// The parts of INPPN and INPTG that CHANGE edited in place.
struct EditedInputs {
  const Edits& points;
  const Edits& tangents;
};

// Makes an interpolated surface the current one: the only change BUILD and CHANGE make to the
// workspace, once everything has been asked and computed. It counts as a new surface
// (Changes::replaced), or with `edited` as the same inputs with those parts new
// (Changes::edited); `derived` is false when PATCHES are not the interpolation of the inputs (as
// FIT's). The surface keeps the tangents it was interpolated with (keep_splines).
void make_current(Workspace& ws, int nocur, int nostr, Density density, Array inppn, Array inptg,
                  Surface surface, SurfaceModes modes = {}, bool derived = true,
                  const EditedInputs* edited = nullptr);

}  // namespace igds
