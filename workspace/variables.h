// The workspace's variables by name (manual section 7, docs/interp.md, "END APL"): one table that
// the session file, the checks of every file and of the APL environment, and the listings read.
// Each variable's element type, rank, shape and limits are stated here and nowhere else.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "workspace/kernels/data_error.h"
#include "workspace/state.h"

namespace igds {

enum class Variable : std::uint8_t {
  nocur,
  nostr,
  intcu,
  intst,
  inppn,
  inptg,
  patches,
  intpn,
  image,
  desim,
  temp1,
  dest1,
  temp2,
  dest2,
  status,
};

// How the session keeps a variable (workspace/disk/session.cpp, docs/disk.md).
enum class Kept : std::uint8_t {
  surface_number,  // NOCUR ... INTST: in the record of the surface
  input,           // INPPN, INPTG: in the record of the surface, in pieces
  derived,         // PATCHES, INTPN: computed again from the inputs, saved only when edited
  image_points,    // IMAGE, TEMP1, TEMP2: a recipe (surface and view) or the points
  image_view,      // DESIM, DEST1, DEST2: with the points of their image
  status,          // STATUS
};

struct VariableInfo {
  Variable id;
  std::string_view name;  // as the manual and the APL environment write it
  Kept kept;
  bool integer;  // elements are whole numbers
  // The rank, and the shape in words (as LIST and the reports say it).
  std::size_t rank;
  std::string_view shape;
  std::string_view meaning;  // one line
};

// The table, in the manual's order.
std::span<const VariableInfo> variables();
const VariableInfo& info(Variable v);
// The variable named `name` (capitals, as the manual writes it); nullptr for any other name.
const VariableInfo* find_variable(std::string_view name);

// The shape an array must have for the numbers NOCUR NOSTR INTCU INTST of `ws` (PATCHES and
// INTPN: their shape once interpolated).
std::vector<std::size_t> expected_shape(const Workspace& ws, Variable v);

// What is wrong with a surface, in the words of a report's reason ("INPPN IS 8 BY 3, NOT 1600 BY
// 3"), naming the variable; nullopt when NOCUR ... INTPN agree with each other and with the
// limits (workspace/kernels/limits.h) and every input number is finite. PATCHES and INTPN may be
// empty (not interpolated) when `allow_empty_surface`. Their numbers are not read (a save checks
// every surface so): whoever brings them from outside checks them with finite_problem.
struct VariableProblem {
  Variable variable;
  std::string reason;
};
// The first number of `a`, the value of `v`, that is not finite (a NaN or an infinity), said with
// its place counted from 1: "POINT 7 OF INPPN IS NOT A FINITE NUMBER", "ROW 3 OF INPTG ...",
// "PATCH 4 OF PATCHES ...", "ROW 3 COLUMN 5 OF INTPN ...", "PLANE 2 ROW 9 OF IMAGE ...",
// "DESIM[3] ..."; nullopt when every number is finite. The one check of finite numbers wherever
// a variable comes from (files, the session, END APL's assignments).
std::optional<VariableProblem> finite_problem(Variable v, const Array& a);
// Why the kernels refused to make a surface from inputs that passed these checks (a result that
// overflowed, a view its points do not allow), in the words of a report's reason: "PATCH 1 IS
// NOT A FINITE NUMBER" (the commands layer words a kernel's refusals of what the user typed).
std::string made_surface_reason(const DataError& e);
// The numbers NOCUR NOSTR INTCU INTST alone: in range and within the limits (checked before any
// array of those sizes is made).
std::optional<VariableProblem> size_problem(int nocur, int nostr, int intcu, int intst);
std::optional<VariableProblem> surface_problem(const Workspace& ws,
                                               bool allow_empty_surface = true);
// The same for an image: DESIM[1] 0 or 1, DESIM[2] a projection of the manual, its parameters
// finite; the points planes x rows x 2 within max_grid_points; the arrows k x 6 (k x 4 in older
// files) or empty; every number finite. With `extent`, the box of the points (Image::extent) is
// found in the same pass as their check, and kept there when they are some.
std::optional<VariableProblem> image_problem(
    const Image& image, Variable points = Variable::image,
    std::optional<std::array<double, 4>>* extent = nullptr);
// STATUS: ten whole numbers; STATUS[1] 0 or 1, STATUS[2] 0, 1 or 2.
std::optional<VariableProblem> status_problem(const std::array<int, 10>& status);

}  // namespace igds
