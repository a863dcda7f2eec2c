// The projections of DISPLAY INPUT and DISPLAY SURFACE (manual 4.4): their words, reading their
// parameters, and asking for the image of the input points or of the interpolated grid.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "commands/context.h"
#include "workspace/images.h"
#include "workspace/state.h"

namespace igds {

// CONIC ISOMETRIC ASSONOMETRIC ORTHOGONAL, then AXONOMETRIC (a synonym after the manual's
// four); code: the Projection.
std::span<const Choice> projection_choices();
// XY YZ XZ; code: the Plane (DESIM[3]).
std::span<const Choice> plane_choices();

// The declared word of a projection (CONIC, ...), of a plane code (XY, ...; "?" for another),
// and of what an image shows (DESIM[1]: INPUT, SURFACE; the words of DISPLAY's options).
std::string_view projection_word(Projection projection);
std::string_view plane_word(double code);
std::string_view image_kind_word(int what);
// HIDDEN, the word of DISPLAY HIDDEN, which a hidden-line image's description adds.
std::string_view hidden_word();

// The parameters of `projection` from the words typed. Throws ParameterError saying what is
// wrong (wrong count, not numbers, out of range).
View parse_view(Projection projection, std::span<const std::string> words);

// The question that asks for a projection's parameters.
const Prompt& parameters_prompt(Projection projection);
extern const Prompt projection_prompt;
// PROJECTION? and the four parameter questions, in that order.
std::span<const Prompt* const> view_questions();

// Asks for the projection and its parameters (from the command line, or question by question)
// and makes the image with `make` (input_image or surface_image of workspace/images.h, or a
// picture's): a bad answer typed at a question gets its report and the question again.
Image ask_image(Context& ctx, const std::function<Image(const Workspace&, const View&)>& make);

}  // namespace igds
