// PLOT's way to the plotter, for whatever else plots a picture (END APL's PLOTG, PLOTP, PLOTV).
#pragma once

#include "commands/context.h"
#include "workspace/drawing/drawing.h"

namespace igds {

// The picture on the plotter as PLOT sends one: a new PLOTnnnn.HPGL on the disk, or --plotter's
// terminal line or path; says where it went.
void plot_picture(Context& ctx, const Picture& picture);

}  // namespace igds
