#include "commands/surface.h"

#include "commands/reports.h"

namespace igds {

Surface interpolate_surface(Workspace& ws, const SurfaceInput& input, bool refit_only) {
  // INTPN is lent to the kernels only when it can be made again from the inputs (the surface is
  // their interpolation): a result refused after it was computed has overwritten it. A refit
  // reads the workspace's own PATCHES (FIT's, or those assigned in END APL), never written over;
  // an interpolation makes none (they are made when read, workspace/state.h).
  const bool lend = ws.changes.derived && ws.has_surface();
  Surface surface;
  if (refit_only) surface.patches = std::move(ws.patches);
  if (lend) surface.intpn = std::move(ws.intpn);
  auto give_back = [&] {
    if (refit_only) ws.patches = std::move(surface.patches);
    if (lend) ws.intpn = std::move(surface.intpn);
  };
  // Inputs near the largest numbers can make a result that is not finite (the kernels find it as
  // they make it): refused before it is kept, and what it overwrote made again as it was (bit for
  // bit: the kernels are exact). A refit makes INTPN alone: PATCHES are the workspace's, finite
  // since they were made.
  std::optional<DataError> overflow;
  try {
    overflow = refit_only ? refit_into(input, surface.patches, surface.intpn)
                          : interpolate_into(input, surface, PatchesOut::dropped);
  } catch (const DataError& e) {
    give_back();
    throw worded(e, "THE SURFACE IS NOT CHANGED");
  } catch (...) {
    give_back();
    throw;
  }
  if (overflow) {
    if (lend) {
      const SurfaceInput before{ws.nocur,  ws.nostr,  ws.intcu,         ws.intst,
                                &ws.inppn, &ws.inptg, ws.marks_twists()};
      // The surface kept: finite when it was made.
      if (refit_only)
        (void)refit_into(before, surface.patches, surface.intpn);
      else
        (void)interpolate_into(before, surface, PatchesOut::dropped);
    }
    give_back();
    throw worded(*overflow, "THE SURFACE IS NOT CHANGED");
  }
  return surface;
}

void make_current(Workspace& ws, int nocur, int nostr, Density density, Array inppn, Array inptg,
                  Surface surface, SurfaceModes modes, bool derived, const EditedInputs* edited) {
  ws.nocur = nocur;
  ws.nostr = nostr;
  ws.intcu = density.intcu;
  ws.intst = density.intst;
  ws.inppn = std::move(inppn);
  ws.inptg = std::move(inptg);
  ws.patches = std::move(surface.patches);
  ws.intpn = std::move(surface.intpn);
  ws.set_surface_modes(modes.marks_twists, modes.auto_tangents);
  if (edited)
    ws.changes.edited(edited->points, edited->tangents);
  else
    ws.changes.replaced();
  ws.changes.derived = derived;
  keep_splines(ws, std::move(surface.tangents));
}

}  // namespace igds
