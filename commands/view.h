// The projections of DISPLAY INPUT and DISPLAY SURFACE (manual 4.4): reading their parameters
// and making the image of the input points or of the interpolated grid.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "workspace/state.h"

namespace igds {

// The projection named by `word` (first match in projection_words(), AXONOMETRIC included).
std::optional<Projection> projection_named(std::string_view word);

// The parameters of `projection` from the words typed; nullopt for INCORRECT PARAMETER (wrong
// count, not numbers, out of range). The view point of CONIC is checked by the image makers.
std::optional<View> parse_view(Projection projection, std::span<const std::string> words);

// DISPLAY INPUT: INPPN projected (NOCUR x NOSTR x 2) and an arrow for every non-zero border
// tangent. Throws Report INCORRECT PARAMETER for a view point inside the points' bounding box
// or a point behind the eye.
Image input_image(const Workspace& ws, const View& view);

// DISPLAY SURFACE: INTPN projected, same checks.
Image surface_image(const Workspace& ws, const View& view);

}  // namespace igds
