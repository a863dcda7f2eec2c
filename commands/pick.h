// Pointing at the current image: a screen address as a point of the image (ZOOM PICK), the input
// point of the surface nearest it (PICK, and PICK at CHANGE POINTS' POINTS?), and in an
// orthogonal view the place in space it stands for. And PICK, the command that names that point.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "commands/context.h"
#include "devices/device.h"
#include "workspace/state.h"

namespace igds {

// A cross-hair pick after `prompt` as a point of the image shown, by the inverse of the placement
// in the pick's layout (devices/layout.h, PickLayout): on the screen, the dialogue's square in
// tek mode and the full one in the Tek window of xterm; on the page (a command file's X Y), the
// full one whatever the mode. Its ZOOM window included. A reply that is not a pick
// gets INCORRECT ENTRY and the cross-hair again. With `rounded`, each coordinate is rounded to the
// power of ten just below one screen point in image units: what a pick can tell, and no more.
Point2 pick_image_point(Context& ctx, const Prompt& prompt, const Image& shown,
                        bool rounded = false);

// True when `shown` shows the input points of the current surface of `ws` (the images
// nearest_input_point can pick on).
bool shows_input_points(const Workspace& ws, const Image& shown);

// The number (1-based) of the input point of the current surface nearest `at` on `shown`: among
// IMAGE's own points of an input image (NOCUR x NOSTR), or the input points' places in the grid
// of a surface or combs image of INTPN's shape. Throws Report when the image shows no input
// points of the current surface (a picture, a file of another surface, another shape).
int nearest_input_point(const Workspace& ws, const Image& shown, Point2 at);

// POINT 7 AT 10 5 2: input point k of `inppn` and its coordinates.
std::string point_words(const Array& inppn, int k);

// In an orthogonal view (DESIM[2] 4), the coordinates of `point` with the two of the view's
// plane set from `at` and the third kept; nullopt for the other projections.
std::optional<std::array<double, 3>> placed_in_view(const Description& desim,
                                                    std::array<double, 3> point, Point2 at);

// The word PICK typed where a pick can answer (ZOOM PICK, PICK at POINTS? and NEW X Y Z?): its
// declaration, for completion, and whether `words` are it.
std::span<const Choice> pick_choices();
bool is_pick(std::span<const std::string_view> words);

// The questions of pointing: the point, and where it goes.
extern const Prompt pick_point_prompt;
extern const Prompt pick_place_prompt;

}  // namespace igds
