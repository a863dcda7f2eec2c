// The entries of BUILD and CHANGE (point, tangent and grid entries, spec igds.md section 3) and
// the small reading helpers the commands share. Parsing is separate from asking, so that it can
// be tested on words alone.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "commands/context.h"
#include "workspace/kernels/array.h"
#include "workspace/kernels/surface.h"
#include "workspace/kernels/vec3.h"
#include "workspace/state.h"

namespace igds {

// Limits that keep a typing slip from asking for gigabytes: input points, and points of INTPN.
inline constexpr std::size_t max_input_points = 1'000'000;
inline constexpr std::size_t max_grid_points = 4'000'000;

// The outcome of parsing an entry: nullopt when it is fine, else the report to print (the
// words of INCORRECT ENTRY, possibly followed by what is wrong).
using EntryOutcome = std::optional<std::string>;

// `k x y z [x y z ...]`: the triplets go to points k, k+1, ... of `inppn` ((NOCUR*NOSTR) x 3).
EntryOutcome apply_point_entry(std::span<const std::string> words, Array& inppn);

// `k tx ty tz` at a border point that is not a corner, `k tx ty tz f` at a corner (f = 1 along
// the curve, 0 along the stringer): sets the matching row of `inptg` (spec igds.md section 3).
EntryOutcome apply_tangent_entry(std::span<const std::string> words, int nocur, int nostr,
                                 Array& inptg);

// NOCUR NOSTR: two integers >= 2 (and not more than max_input_points points).
struct GridSize {
  int nocur = 0, nostr = 0;
};
std::optional<GridSize> parse_grid_size(std::span<const std::string> words);

// INTCU INTST: two integers >= 0 giving at most max_grid_points points of INTPN.
struct Density {
  int intcu = 0, intst = 0;
};
EntryOutcome parse_density(std::span<const std::string> words, int nocur, int nostr,
                           Density& density);

// The INPTG row of the tangent at point k (1-based) along the curve (along_curve) or along the
// stringer; -1 when k is not a border point of that kind.
int tangent_row(int k, bool along_curve, int nocur, int nostr);

// INPTG of a new surface: zero tangents, the point number of every row in column 4.
Array zero_tangents(int nocur, int nostr);

// A whole number written as a number word (`3`, `3.0`, `3E0`), within [low, high].
std::optional<long long> parse_integer(std::string_view word, long long low, long long high);

// Y, YES, N, NO (any case, any prefix): true for yes.
std::optional<bool> parse_yes_no(std::span<const std::string> words);

// The words of the projections of DISPLAY, in lookup order (AXONOMETRIC is a synonym of
// ASSONOMETRIC, after the four of the manual); completion offers them too.
std::span<const std::string_view> projection_words();

// The asks and entry loops of BUILD and CHANGE (each ends with an empty line).
void ask_point_entries(Context& ctx, Array& inppn);
void ask_tangent_entries(Context& ctx, int nocur, int nostr, Array& inptg);
Density ask_density(Context& ctx, int nocur, int nostr);
// The prompts of these entries, for the follow-up questions of CHANGE.
extern const Prompt points_prompt;
extern const Prompt tangents_prompt;
extern const Prompt density_prompt;

// COONS then FIT; a kernel's DataError becomes a Report (the surface in the workspace is kept).
Surface interpolate_surface(int nocur, int nostr, Density density, const Array& inppn,
                            const Array& inptg);

// Makes an interpolated surface the current one: the only change BUILD and CHANGE make to the
// workspace, once everything has been asked and computed.
void make_current(Workspace& ws, int nocur, int nostr, Density density, Array inppn, Array inptg,
                  Surface surface);

// Throws INCORRECT COMMAND OR PARAMETERS when words are left on the command line.
void expect_no_more_words(Context& ctx);

}  // namespace igds
