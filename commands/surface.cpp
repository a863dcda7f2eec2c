#include "commands/surface.h"

#include "commands/reports.h"

namespace igds {

Surface interpolate_surface(Workspace& ws, const SurfaceInput& input, bool refit_only) {
  Surface surface{std::move(ws.patches), std::move(ws.intpn)};
  auto give_back = [&] {
    ws.patches = std::move(surface.patches);
    ws.intpn = std::move(surface.intpn);
  };
  try {
    if (refit_only)
      refit_into(input, surface.patches, surface.intpn);
    else
      interpolate_into(input, surface);
  } catch (const DataError& e) {
    give_back();
    throw worded(e, "THE SURFACE IS NOT CHANGED");
  } catch (...) {
    give_back();
    throw;
  }
  return surface;
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
