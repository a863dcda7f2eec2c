// UNDO and REDO driven through a scripted Context, the journal recording each command as the
// interpreter does after it.
#include <doctest/doctest.h>

#include "commands/command.h"
#include "tests/support/fake_context.h"
#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "workspace/error.h"
#include "workspace/state.h"

namespace igds {
extern const Command build_command;
extern const Command change_command;
extern const Command undo_command;
extern const Command redo_command;
}  // namespace igds

namespace igds::test {

namespace {

const std::vector<std::string> saddle{"3 3",
                                      "1  0 0 0   0 10 2   0 20 0",
                                      "4  10 0 2  10 10 0  10 20 2",
                                      "7  20 0 0  20 10 2  20 20 0",
                                      "",
                                      "1 0 1 0 1",
                                      "",
                                      "2 2"};

// A command run, then recorded in the journal and the Edits forgotten (the interpreter's save).
void run(FakeContext& ctx, const Command& c, std::string_view option, std::string name,
         std::vector<std::string> lines = {}) {
  ctx.type(std::move(lines));
  ctx.run(c, option);
  ctx.undo_journal.record(ctx.ws, name);
  ctx.ws.changes.inppn.saved();
  ctx.ws.changes.inptg.saved();
}

}  // namespace

TEST_CASE("UNDO says what it undid, REDO what it made again; nothing left: a report") {
  TempDir dir;
  FakeContext ctx(dir.path());
  CHECK(report_of(ctx, undo_command, "") == "NOTHING TO UNDO");
  CHECK(report_of(ctx, redo_command, "") == "NOTHING TO REDO");

  run(ctx, build_command, "", "BUILD", saddle);
  const Workspace built = ctx.ws;
  run(ctx, change_command, "POINTS", "CHANGE POINTS", {"5 10 10 7", "", "N", "N"});
  const Workspace changed = ctx.ws;
  CHECK(changed.inppn.ravel[14] == 7);

  ctx.run(undo_command, "");
  CHECK(ctx.said.back() == "UNDONE: CHANGE POINTS");
  CHECK(ctx.ws == built);
  ctx.run(undo_command, "");
  CHECK(ctx.said.back() == "UNDONE: BUILD");
  CHECK(!ctx.ws.has_input());
  CHECK(report_of(ctx, undo_command, "") == "NOTHING TO UNDO");
  ctx.run(redo_command, "");
  CHECK(ctx.said.back() == "REDONE: BUILD");
  ctx.run(redo_command, "");
  CHECK(ctx.said.back() == "REDONE: CHANGE POINTS");
  CHECK(ctx.ws == changed);
  CHECK(report_of(ctx, redo_command, "") == "NOTHING TO REDO");

  // A change after UNDO: what REDO had is gone.
  ctx.run(undo_command, "");
  run(ctx, change_command, "POINTS", "CHANGE POINTS", {"1 0 0 -3", "", "N", "N"});
  CHECK(report_of(ctx, redo_command, "") == "NOTHING TO REDO");
  ctx.run(undo_command, "");
  CHECK(ctx.ws == built);
  // Words after UNDO are not taken.
  CHECK(report_of(ctx, undo_command, "", {"2"}) == "INCORRECT COMMAND OR PARAMETERS");
  CHECK(ctx.ws == built);
}

TEST_CASE("a surface keeps the tangents it was interpolated with, its own after every change") {
  TempDir dir;
  FakeContext ctx(dir.path());
  run(ctx, build_command, "", "BUILD", saddle);
  check_kept_splines(ctx.ws);
  run(ctx, change_command, "POINTS", "CHANGE POINTS", {"5 10 10 7", "", "N", "N"});
  check_kept_splines(ctx.ws);
  run(ctx, change_command, "TANGENTS", "CHANGE TANGENTS", {"1 0 2 0 1", "", "N"});
  check_kept_splines(ctx.ws);
  run(ctx, change_command, "TWISTS", "CHANGE TWISTS", {"MARKS"});
  CHECK(ctx.ws.marks_twists());
  check_kept_splines(ctx.ws);
  for (int k = 0; k < 3; ++k) {
    ctx.run(undo_command, "");
    check_kept_splines(ctx.ws);
  }
  for (int k = 0; k < 3; ++k) {
    ctx.run(redo_command, "");
    check_kept_splines(ctx.ws);
  }
  // Another generation of the surface, tangents of another grid or twists that are not the
  // surface's: not read.
  Workspace other = ctx.ws;
  other.changes.replaced();
  CHECK(kept_splines(other) == nullptr);
  other = ctx.ws;
  auto smaller = std::make_shared<SplineTangents>(*ctx.ws.splines.made);
  smaller->tangents.along_curves.pop_back();
  other.splines.made = smaller;
  CHECK(kept_splines(other) == nullptr);
  other = ctx.ws;
  auto zero = std::make_shared<SplineTangents>(*ctx.ws.splines.made);
  zero->twists = Array();
  other.splines.made = zero;
  CHECK(kept_splines(other) == nullptr);
  // PATCHES the workspace holds (not the interpolation's) are read, not made.
  other = ctx.ws;
  other.changes.derived = false;
  CHECK(kept_splines(other) == nullptr);
}

}  // namespace igds::test
