// The entries of BUILD and CHANGE: point, tangent and grid entries (docs/interp.md, "The
// questions"), their questions, and the loops that ask for them. Parsing is separate from asking,
// so that it can be tested on words alone.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "commands/context.h"
#include "workspace/kernels/array.h"
#include "workspace/kernels/limits.h"
#include "workspace/state.h"

namespace igds {

// `k x y z [x y z ...]`: the triplets go to points k, k+1, ... of `inppn` ((NOCUR*NOSTR) x 3).
// Throws EntryError (INCORRECT ENTRY with what is wrong); only a correct entry changes anything.
// The elements it changed are added to `edits` when given.
void apply_point_entry(std::span<const std::string_view> words, Array& inppn,
                       Edits* edits = nullptr);

// `k tx ty tz` at a border point that is not a corner, `k tx ty tz f` at a corner (f = 1 along
// the curve, 0 along the stringer): sets the matching row of `inptg` (docs/interp.md, "The
// questions"). Throws EntryError. The row it changed is added to `edits` when given.
void apply_tangent_entry(std::span<const std::string_view> words, int nocur, int nostr,
                         Array& inptg, Edits* edits = nullptr);

// AUTO at TANGENTS? (docs/marks.md): every border tangent of `inptg` set by Marks's rule from
// the points of `inppn`, per unit of chord so that PATCHES holds Marks's vectors. Entries typed
// after it override single tangents.
void apply_auto_tangents(int nocur, int nostr, const Array& inppn, Array& inptg,
                         Edits* edits = nullptr);
// True when `words` is the AUTO entry (the word AUTO or a prefix of it, case ignored).
bool is_auto_entry(std::span<const std::string_view> words);

// NOCUR NOSTR: two whole numbers >= 1, at least two points, at most max_input_points.
struct GridSize {
  int nocur = 0, nostr = 0;
};
GridSize parse_grid_size(std::span<const std::string_view> words);  // throws EntryError

// INTCU INTST: two whole numbers >= 0 giving at most max_grid_points points of INTPN.
struct Density {
  int intcu = 0, intst = 0;
};
Density parse_density(std::span<const std::string_view> words, int nocur, int nostr);  // EntryError

// The INPTG row of the tangent at point k (1-based) along the curve (along_curve) or along the
// stringer; -1 when k is not a border point of that kind. A line of one point has no tangent:
// a single curve (NOCUR 1) has only its two ends, a single stringer (NOSTR 1) likewise.
int tangent_row(int k, bool along_curve, int nocur, int nostr);

// INPTG of a new surface: zero tangents, the point number of every row in column 4.
Array zero_tangents(int nocur, int nostr);

// The questions of these entries.
extern const Prompt size_prompt;
extern const Prompt points_prompt;
extern const Prompt tangents_prompt;
extern const Prompt density_prompt;

// The asks and entry loops of BUILD and CHANGE (point and tangent entries end with an empty
// line; a wrong entry gets its report and the next one is awaited).
GridSize ask_grid_size(Context& ctx);
void ask_point_entries(Context& ctx, Array& inppn, Edits* edits = nullptr);
// The tangent entries: true when AUTO was among them (`inppn` gives its points).
bool ask_tangent_entries(Context& ctx, int nocur, int nostr, const Array& inppn, Array& inptg,
                         Edits* edits = nullptr);
Density ask_density(Context& ctx, int nocur, int nostr);

}  // namespace igds
