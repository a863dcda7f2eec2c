#include "commands/surface.h"

#include "commands/reports.h"

namespace igds {

Surface interpolate_surface(int nocur, int nostr, Density density, const Array& inppn,
                            const Array& inptg, bool marks_twists) {
  SurfaceInput input{nocur, nostr, density.intcu, density.intst, &inppn, &inptg, marks_twists};
  try {
    return interpolate(input);
  } catch (const DataError& e) {
    throw worded(e, "THE SURFACE IS NOT CHANGED");
  }
}

void make_current(Workspace& ws, int nocur, int nostr, Density density, Array inppn, Array inptg,
                  Surface surface, SurfaceModes modes, bool derived) {
  ws.nocur = nocur;
  ws.nostr = nostr;
  ws.intcu = density.intcu;
  ws.intst = density.intst;
  ws.inppn = std::move(inppn);
  ws.inptg = std::move(inptg);
  ws.patches = std::move(surface.patches);
  ws.intpn = std::move(surface.intpn);
  ws.set_surface_modes(modes.marks_twists, modes.auto_tangents);
  ws.changes.replaced(derived);
}

}  // namespace igds
