// Numbers that are not finite never enter the workspace: a typed number so large that the surface
// it makes overflows is refused at BUILD, CHANGE and FIT with the manual's report, and the
// workspace is as it was, bit for bit; the reports of what cannot be written name the patch,
// curve or point, counted from 1, that is at fault.
#include <doctest/doctest.h>

#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands/command.h"
#include "tests/support/fake_context.h"
#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "workspace/error.h"
#include "workspace/kernels/limits.h"

namespace igds {
extern const Command build_command;
extern const Command change_command;
extern const Command fit_command;
extern const Command punch_command;
extern const Command export_command;
}  // namespace igds

namespace igds::test {

namespace {

const std::vector<std::string> saddle{"3 3",
                                      "1  0 0 0   0 10 2   0 20 0",
                                      "4  10 0 2  10 10 0  10 20 2",
                                      "7  20 0 0  20 10 2  20 20 0",
                                      "",
                                      "",
                                      "2 2"};

// A workspace whose patches and grid are finite but so large that their Bézier controls are not
// (patch 2 of 2 and the points of INTPN it makes: the first patch is an ordinary one).
Workspace huge_second_patch() {
  Workspace ws = make_interpolated(2, 3, 1, 1);
  ws.image = ws.temp1 = ws.temp2 = nullptr;
  own_surface(ws);
  for (std::size_t k = 0; k < 48; ++k) ws.patches.ravel[48 + k] = 1.5e308;
  for (std::size_t row = 0; row < 3; ++row)
    for (std::size_t column = 3; column < 5; ++column)
      for (std::size_t c = 0; c < 3; ++c) ws.intpn.ravel[3 * (5 * row + column) + c] = 1.7e308;
  return ws;
}

}  // namespace

TEST_CASE(
    "a tangent of 1E308 overflows the surface: refused at CHANGE and BUILD, nothing changed") {
  TempDir dir;
  FakeContext ctx(dir.path());
  ctx.type(saddle);
  ctx.run(build_command, "");
  const Workspace before = ctx.ws;
  // Along the curve at point 1: finite as typed, but the patches it makes are not.
  ctx.type({"1 1E308 0 0 1", "", "N"});
  CHECK(report_of(ctx, change_command, "T") ==
        "INCORRECT ENTRY: PATCH 1 IS NOT A FINITE NUMBER; THE SURFACE IS NOT CHANGED");
  check_same_surface(ctx.ws, before);
  CHECK(ctx.ws.changes.surface == before.changes.surface);
  // The same at CHANGE POINTS then its tangents, and at BUILD.
  ctx.type({"5 10 10 1", "", "Y", "3 0 1E308 0 1", "", "N"});
  CHECK(report_of(ctx, change_command, "P")
            .ends_with("IS NOT A FINITE NUMBER; THE SURFACE IS NOT CHANGED"));
  check_same_surface(ctx.ws, before);
  std::vector<std::string> build = saddle;
  build[5] = "1 1E308 0 0 1";
  build.insert(build.begin() + 6, "");
  ctx.type(build);
  CHECK(report_of(ctx, build_command, "")
            .ends_with("IS NOT A FINITE NUMBER; THE SURFACE IS NOT CHANGED"));
  check_same_surface(ctx.ws, before);
}

TEST_CASE("a surface whose patches are FIT's keeps them when a CHANGE overflows") {
  // FIT's patches are not the interpolation of the inputs: they are never lent to the kernels
  // for a result that could be refused after it overwrote them.
  TempDir dir;
  FakeContext ctx(dir.path());
  ctx.type(saddle);
  ctx.run(build_command, "");
  own_surface(ctx.ws);
  for (double& v : ctx.ws.patches.ravel) v *= 1.0000001;
  const Workspace before = ctx.ws;
  ctx.type({"1 1E308 0 0 1", "", "N"});
  CHECK(report_of(ctx, change_command, "T").ends_with("THE SURFACE IS NOT CHANGED"));
  check_same_surface(ctx.ws, before);
}

TEST_CASE("a Marks deck whose numbers overflow the fit is refused, the surface kept") {
  TempDir dir;
  FakeContext ctx(dir.path());
  ctx.type(saddle);
  ctx.run(build_command, "");
  const Workspace before = ctx.ws;
  write_file(dir.path() / "HUGE.CADADATA",
             "   2   2\n"
             "   1   1   1   1\n"
             "-1.E308    0.0    0.0\n"
             "1.0E308    0.0    0.0\n"
             "    0.0   10.0    0.0\n"
             "   10.0   10.0    0.0\n");
  ctx.type({"0 0"});
  const std::string r = report_of(ctx, fit_command, "", {"HUGE"});
  CAPTURE(r);
  CHECK(r.find("IS NOT A FINITE NUMBER") != std::string::npos);
  CHECK((r.ends_with("THE SURFACE IS NOT CHANGED") || r.ends_with("CURRENT SURFACE KEPT")));
  check_same_surface(ctx.ws, before);
}

TEST_CASE("PUNCH of more patches than the tape can number says so") {
  TempDir dir;
  FakeContext ctx(dir.path());
  // 2 x 131074 points: 131073 patches, one more than 18 bits number.
  const std::size_t columns = 131074;
  ctx.ws.nocur = 2;
  ctx.ws.nostr = static_cast<int>(columns);
  ctx.ws.inppn = Array({2 * columns, 3});
  ctx.ws.inptg = Array({2 * (2 + columns), 4});
  ctx.ws.patches = Array({1, columns - 1, 3, 4, 4});
  ctx.ws.intpn = Array({2, columns, 3});
  CHECK(report_of(ctx, punch_command, "", {"LONG"}) ==
        "131073 PATCHES: THE TAPE NUMBERS AT MOST 131071; NO FILE WRITTEN");
}

TEST_CASE("EXPORT of a surface whose Bezier controls overflow names the patch or the stringer") {
  TempDir dir;
  FakeContext ctx(dir.path(), huge_second_patch());
  CHECK(report_of(ctx, export_command, "IGES", {"BIG"}) ==
        "INCORRECT ENTRY: PATCH 2 HAS BEZIER CONTROLS THAT ARE NOT FINITE NUMBERS; NO FILE "
        "WRITTEN");
  CHECK(report_of(ctx, export_command, "STEP", {"BIG"}) ==
        "INCORRECT ENTRY: PATCH 2 HAS BEZIER CONTROLS THAT ARE NOT FINITE NUMBERS; NO FILE "
        "WRITTEN");
  CHECK(report_of(ctx, export_command, "DUCT", {"BIG"}) ==
        "INCORRECT ENTRY: STRINGER 4 HAS A NUMBER THAT IS NOT FINITE IN THE DUCT PICTURE; NO FILE "
        "WRITTEN");
  CHECK(std::filesystem::is_empty(dir.path()));
}

}  // namespace igds::test
