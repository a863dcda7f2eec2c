// The images of DISPLAY INPUT and DISPLAY SURFACE (manual 4.4): the input points or the
// interpolated grid of a surface, projected as a view says. The commands make them; the session
// makes them again at start from the surface they were drawn from (Image::drawn_from), so the
// same function makes both, bit for bit.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "workspace/kernels/project.h"
#include "workspace/state.h"

namespace igds {

// DISPLAY INPUT: INPPN projected (NOCUR x NOSTR x 2) and an arrow for every non-zero border
// tangent (Image::arrows). DISPLAY SURFACE: INTPN projected; DISPLAY HIDDEN's
// adds how near each point is to the eye (Image::nearness). Both throw DataError
// (view_inside_box for a view point inside the points' bounding box, behind_eye, ...).
Image input_image(const Workspace& ws, const View& view);
Image surface_image(const Workspace& ws, const View& view);
Image hidden_surface_image(const Workspace& ws, const View& view);
// DISPLAY COMBS: the surface image (DESIM[1] 3) and the curvature combs of its curves and
// stringers (Image::combs, docs/kernels.md "Curvature"): at every point of INTPN a comb away from
// the centre of curvature, of length comb_scale times the curvature, comb_scale the number 1, 2 or
// 5 times a power of ten that makes the largest comb at most comb_fraction of the grid's larger
// side (0 when no line bends): a number of the surface, read from combs already drawn from it
// when IMAGE, FIRST or SECOND holds them (docs/kernels.md, "Curvature").
Image comb_image(const Workspace& ws, const View& view);
inline constexpr double comb_fraction = 0.2;
// The scale of the combs: largest curvature `most` on a grid `extent` long.
double comb_scale_for(double extent, double most);
// The rows of INTPN whose largest curvature is DISPLAY COMBS CONIC's guess of the scale of a
// surface's first combs (docs/kernels.md, "Curvature"), in increasing order: every eighth row of
// patches, and the rows of patches on either side of the input point where an input curve, and
// where an input stringer, bends most sharply. A grid of NOCUR > 1 and NOSTR > 1.
std::vector<std::size_t> comb_guess_rows(const Workspace& ws);

// DISPLAY PICTURE: the DUCT picture `text` of NAME.DUCTPIC drawn in space (duct_drawing of
// workspace/exchange/duct.h) and seen as `view` says, CONIC towards the centre of the picture's
// bounding box (control points included). DESIM[1] is 2; IMAGE is empty, the drawing is in
// Image::picture. Throws DuctError for a damaged or foreign picture, DataError for a view the
// picture does not allow (view_inside_box, behind_eye, ...).
Image picture_image(std::string name, std::string text, const View& view);
// The same, with the picture already read and drawn in space from `text` (`drawing`).
Image picture_image(std::string name, std::string text, const Drawing3& drawing, const View& view);

// The image `desim` describes (DESIM[1] 0 input, 1 surface, 3 combs) of the surface of `ws` (a
// picture image, DESIM[1] 2, is made by picture_image from its text, not from a surface).
Image image_of(const Workspace& ws, const Description& desim);
// The same image of the surface whose inputs `source` holds (its generation in
// changes.surface), made when it is first looked at (a surface image interpolates the inputs
// then): an image the session or the undo journal kept by its recipe.
ImageRef image_by_recipe(std::shared_ptr<const Workspace> source, const Description& desim);
// The same with the surface's inputs made only then, by `source` (the state of a journal read
// from the disk, workspace/journal.h JournalStates); `generation` the one they will say.
ImageRef image_by_recipe(std::function<Workspace()> source, std::uint64_t generation,
                         const Description& desim);

}  // namespace igds
