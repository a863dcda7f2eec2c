// The conversation on a session forged with valid frames and checksums (tests/workspace/forge.h):
// whatever a layer below throws while a command runs or the session is saved, igds says why and
// goes on; nothing that is not a finite number enters the workspace.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "interp/interpreter.h"
#include "tests/support/process.h"
#include "tests/support/scripted.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/forge.h"
#include "workspace/disk/session.h"
#include "workspace/images.h"
#include "workspace/journal.h"

namespace igds::test {

namespace {

// The conversation on `disk` with `lines` typed, as igds has it (the notices of the start, each
// command, the save after it and at the end); what it said.
std::string converse(const Disk& disk, const std::vector<std::string>& lines) {
  StringOutput out;
  ScriptedSource input(false, true);
  input.lines(lines);
  Options options;
  options.disk = disk.dir();
  Session session(disk);
  Terminal terminal(options.term, options.tek, out);
  Interpreter interpreter(options, disk, session, session.load(), terminal);
  terminal.use_input(&input);
  terminal.begin();
  for (const auto& notice : session.notices()) interpreter.say(notice);
  interpreter.converse();
  interpreter.save();
  return out.text;
}

// CHANGE POINTS of point k (0-based): its z, interpolated again, as commands/change.cpp does.
void change_point(Workspace& ws, std::size_t k, double z) {
  ws.inppn.ravel[3 * k + 2] = z;
  Edits points = Edits::none();
  points.part(3 * k, 3 * k + 3);
  ws.changes.edited(points, Edits::none());
  Surface s = interpolate({ws.nocur, ws.nostr, ws.intcu, ws.intst, &ws.inppn, &ws.inptg});
  ws.patches = std::move(s.patches);
  ws.intpn = std::move(s.intpn);
}

// Two UNDOs on `disk`: the first to a state holding an image that cannot be drawn, the second
// to the state before, `first`.
void two_undos(const Disk& disk, const Workspace& first) {
  const std::string said = converse(disk, {"UNDO", "UNDO"});
  CAPTURE(said);
  CHECK(said.find("TEMP1 CANNOT BE DRAWN AGAIN (THE VIEW POINT IS INSIDE THE SURFACE'S BOX): NOT "
                  "KEPT IN THE SESSION") != std::string::npos);
  // Said once, though the image stays until something replaces it.
  CHECK(said.find("CANNOT BE DRAWN AGAIN") == said.rfind("CANNOT BE DRAWN AGAIN"));
  CHECK(said.find("CANNOT SAVE") == std::string::npos);
  // The session on the disk is the state after the two UNDOs, without that image.
  Session session(disk);
  Workspace back = session.load();
  CHECK(session.notices().empty());
  check_same_surface(back, first);
  CHECK(!back.temp1);
}

}  // namespace

TEST_CASE("UNDO to a state holding an image its surface cannot draw: said, and igds goes on") {
  TempDir dir;
  Disk disk(dir.path());
  // Three states; the middle one holds as TEMP1 an image of the first, by its recipe: a CONIC
  // view from inside the points' box, which DISPLAY refuses and a forged journal can say.
  Workspace ws = make_interpolated(4, 4, 1, 1);
  ws.image = ws.temp1 = ws.temp2 = nullptr;
  ws.changes.inppn.saved();
  ws.changes.inptg.saved();
  Journal journal(ws);
  auto first = std::make_shared<Workspace>(ws);
  const Description inside{0, Projection::conic, {15, 10, 0}};
  change_point(ws, 5, 2);
  ws.temp1 = image_by_recipe(first, inside);
  REQUIRE(journal.record(ws, "CHANGE POINTS"));
  ws.changes.inppn.saved();
  change_point(ws, 6, 3);
  ws.temp1 = nullptr;
  REQUIRE(journal.record(ws, "CHANGE POINTS"));
  {
    Session session(disk);
    session.load();
    session.save(ws, &journal);
  }
  REQUIRE(!forge::session_table(disk).journal.empty());

  SUBCASE("the image kept out stays where UNDO put it: the journal names it by no slot") {
    const std::string said = converse(disk, {"UNDO"});
    CHECK(said.find("TEMP1 CANNOT BE DRAWN AGAIN") != std::string::npos);
    Session session(disk);
    Workspace back = session.load();
    CHECK(session.notices().empty());
    CHECK(!back.temp1);
  }
  SUBCASE("a second UNDO goes on") {
    two_undos(disk, *first);
  }
}

}  // namespace igds::test
