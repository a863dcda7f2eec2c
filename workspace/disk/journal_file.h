// The undo journal as the session file keeps it (its last section, docs/disk.md): the steps with
// the values they changed, and each image they name once, as a slot of the session (the same
// image as IMAGE, TEMP1 or TEMP2 now), a recipe (a state of the journal and DESIM), or its
// points when small. A journal read back is checked like everything else on the disk.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "workspace/journal.h"
#include "workspace/state.h"

namespace igds::disk {

// An image kept by its points in the journal is at most this large (encoded); a step that needs
// a larger one that is neither a slot nor a recipe is not kept on the disk (nor the steps beyond).
inline constexpr std::size_t journal_image_limit = 256u << 10;
// And all the images it keeps by their points together.
inline constexpr std::size_t journal_images_limit = 2u << 20;
// The values of one step's INPPN and INPTG on the disk, and of all steps: the session file (and
// the journal in it) is written again after every change, so that a step that replaced a large
// surface whole (BUILD, RESTORE of more than about 45 x 45 points) is undone in this run only.
inline constexpr std::size_t journal_step_limit = 64u << 10;
inline constexpr std::size_t journal_values_limit = 512u << 10;

// The journal saved with `ws` (its images are named by slot, not written again).
std::string encode_journal(const Journal& journal, const Workspace& ws);
// The same when the session keeps only `slots` of the workspace's images (one it could not draw
// is kept out: the journal must not name it by its slot).
std::string encode_journal(const Journal& journal, const ImageSlots& slots);

// The journal saved with `ws`, checked (Journal::rebuild, image_problem); throws Damage with the
// reason for anything malformed or that does not fit `ws`. `lost`: the slots (IMAGE, TEMP1,
// TEMP2) whose image the session could not read back; the states that had it have no image.
Journal decode_journal(std::string_view bytes, const Workspace& ws, std::array<bool, 3> lost = {});

}  // namespace igds::disk
