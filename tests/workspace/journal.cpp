// The undo journal (workspace/journal.h) and its place in the session file
// (workspace/disk/journal_file.h): steps, bounds, redo dropped, images by slot, recipe or points,
// a crafted journal refused.
#include "workspace/journal.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include "tests/workspace/disk_fixtures.h"
#include "workspace/disk/files.h"
#include "workspace/disk/frame.h"
#include "workspace/disk/journal_file.h"
#include "workspace/disk/session.h"
#include "workspace/disk/session_file.h"
#include "workspace/images.h"
#include "workspace/kernels/data_error.h"
#include "workspace/kernels/surface.h"
#include "workspace/variables.h"

using namespace igds;
namespace fs = std::filesystem;

namespace {

// What the session does once a step is recorded: the Edits start again.
void saved(Workspace& ws) {
  ws.changes.inppn.saved();
  ws.changes.inptg.saved();
}

// CHANGE POINTS of point k (0-based): its z, as commands/change.cpp records it.
void change_point(Workspace& ws, std::size_t k, double z, bool interpolated = true) {
  ws.inppn.ravel[3 * k + 2] = z;
  Edits points = Edits::none();
  points.part(3 * k, 3 * k + 3);
  ws.changes.edited(points, Edits::none());
  if (!interpolated) return;
  Surface s = interpolate({ws.nocur, ws.nostr, ws.intcu, ws.intst, &ws.inppn, &ws.inptg});
  ws.patches = std::move(s.patches);
  ws.intpn = std::move(s.intpn);
}

// A command: `change` then the step recorded and the Edits forgotten, as the interpreter does.
template <typename F>
bool command(Journal& j, Workspace& ws, std::string_view name, F change) {
  change();
  const bool recorded = j.record(ws, name);
  saved(ws);
  return recorded;
}

}  // namespace

TEST_CASE("UNDO and REDO go through the states; a new change drops the states REDO had") {
  Workspace ws = test::make_interpolated(4, 5, 2, 2);
  saved(ws);
  Journal j(ws);
  std::vector<Workspace> states{ws};
  for (int k = 0; k < 3; ++k) {
    CHECK(command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 3 + k, 1.5 * k); }));
    states.push_back(ws);
  }
  CHECK(command(j, ws, "DISPLAY INPUT", [&] {
    ws.image = std::make_shared<const Image>(image_of(ws, {0, Projection::conic, {90, 80, 70}}));
  }));
  states.push_back(ws);
  CHECK(command(j, ws, "HELP SHORT", [&] { ws.status[0] = 0; }));
  states.push_back(ws);
  // Nothing changed: no step.
  CHECK_FALSE(command(j, ws, "ERASE", [] {}));
  CHECK(j.undo_count() == 5);

  const std::vector<std::string> names{"HELP SHORT", "DISPLAY INPUT", "CHANGE POINTS",
                                       "CHANGE POINTS", "CHANGE POINTS"};
  for (std::size_t k = 0; k < 5; ++k) {
    CAPTURE(k);
    CHECK(j.undo(ws) == names[k]);
    test::check_same_workspace(ws, states[4 - k]);
    // UNDO itself is no step of the journal.
    CHECK_FALSE(j.record(ws, "UNDO"));
    saved(ws);
  }
  CHECK(j.undo(ws) == std::nullopt);
  test::check_same_workspace(ws, states[0]);
  CHECK(j.redo(ws) == "CHANGE POINTS");
  test::check_same_workspace(ws, states[1]);
  CHECK(j.redo_count() == 4);
  // The images are the same ones, not copies.
  CHECK(ws.image == states[1].image);

  CHECK(command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 0, -4); }));
  CHECK(j.redo_count() == 0);
  CHECK(j.redo(ws) == std::nullopt);
  CHECK(j.undo(ws) == "CHANGE POINTS");
  test::check_same_workspace(ws, states[1]);
}

TEST_CASE("a step keeps what its command changed; the journal is bounded in steps and bytes") {
  Workspace ws = test::make_interpolated(100, 100, 0, 0);
  saved(ws);
  Journal j(ws);
  const Workspace first = ws;
  for (int k = 0; k < 300; ++k)
    command(j, ws, "CHANGE POINTS",
            [&] { change_point(ws, std::size_t(k * 37) % 10000, k, false); });
  CHECK(j.undo_count() == Journal::max_steps);
  // One point: 3 values before and after, and a range; nothing of the 240 KB of INPPN.
  CHECK(j.bytes() < Journal::max_steps * 256);
  MESSAGE("journal after 300 one-point changes of 100 x 100: ", j.bytes(), " bytes");

  // A surface replaced whole, larger than the bound: the journal starts again after it.
  CHECK(command(j, ws, "BUILD", [&] {
    ws.nocur = ws.nostr = 420;
    ws.inppn = Array({420 * 420, 3});
    ws.inptg = Array({2 * 840, 4});
    ws.changes.replaced();
  }));
  CHECK(j.undo_count() == 0);
  CHECK(j.bytes() == 0);
  CHECK(j.undo(ws) == std::nullopt);
  // ... from the state that step left: the next step is recorded from it, and undone to it.
  const Array built = ws.inppn;
  CHECK(command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 5, 1.5); }));
  CHECK(j.undo_count() == 1);
  CHECK(j.undo(ws) == "CHANGE POINTS");
  CHECK(ws.inppn == built);
}

TEST_CASE("a step of the journal's bound in bytes is kept, and one of a double more is not") {
  // Replaced whole (another shape): the step keeps both arrays whole, before and after.
  const std::string name = "BUILD";
  const std::size_t room =
      (Journal::max_bytes - name.size() - 2 * sizeof(Settings)) / sizeof(double);
  for (const std::size_t extra : {0, 1}) {
    Workspace ws = test::make_interpolated(10, 10, 0, 0);
    saved(ws);
    Journal j(ws);
    CHECK(command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 5, 1.5, false); }));
    // INPTG of one row; INPPN of as many rows as fill the room (a row of 4 doubles less or more
    // where 3 does not divide what is left).
    const std::size_t before = ws.inppn.size() + ws.inptg.size(), left = room + extra - before;
    const std::size_t rows_tg = 1 + (left - 4) % 3, rows_pn = (left - 4 * rows_tg) / 3;
    REQUIRE(3 * rows_pn + 4 * rows_tg == left);
    CHECK(command(j, ws, name, [&] {
      ws.inppn = Array({rows_pn, 3});
      ws.inptg = Array({rows_tg, 4});
      ws.changes.replaced();
    }));
    CAPTURE(extra);
    if (extra == 0) {
      // Kept, and the step before it made room for it.
      CHECK(j.undo_count() == 1);
      CHECK(j.bytes() <= Journal::max_bytes);
      CHECK(j.bytes() > Journal::max_bytes - sizeof(double));
      CHECK(j.undo(ws) == name);
    } else {
      CHECK(j.undo_count() == 0);
      CHECK(j.bytes() == 0);
    }
  }
}

TEST_CASE("the journal on the disk: images by slot, by recipe or by their points, read back") {
  Workspace ws = test::make_interpolated(20, 20, 4, 4);
  saved(ws);
  Journal j(ws);
  std::vector<Workspace> states{ws};
  auto step = [&](std::string_view name, auto change) {
    REQUIRE(command(j, ws, name, change));
    states.push_back(ws);
  };
  step("CHANGE POINTS", [&] { change_point(ws, 7, 2.5); });
  step("DISPLAY SURFACE", [&] {
    ws.image = std::make_shared<const Image>(image_of(ws, {1, Projection::orthogonal, {1, 0, 0}}));
  });
  step("STORE FIRST", [&] { ws.temp1 = ws.image; });
  step("CHANGE POINTS", [&] { change_point(ws, 30, -1); });
  // An image that is no recipe (DISPLAY FILE), small: kept by its points.
  step("DISPLAY FILE", [&] {
    ws.image = std::make_shared<const Image>(test::make_image(0, Projection::conic, 3, 4, 9));
  });
  step("DISPLAY SURFACE", [&] {
    ws.image = std::make_shared<const Image>(image_of(ws, {1, Projection::isometric, {3, 30, 0}}));
  });
  step("CHANGE GRID", [&] {
    ws.intcu = 2;
    ws.changes.edited(Edits::none(), Edits::none());
    Surface s = interpolate({ws.nocur, ws.nostr, ws.intcu, ws.intst, &ws.inppn, &ws.inptg});
    ws.patches = std::move(s.patches);
    ws.intpn = std::move(s.intpn);
  });
  // Two steps undone: REDO's steps are on the disk too.
  j.undo(ws);
  j.undo(ws);
  saved(ws);

  const std::string bytes = disk::encode_journal(j, ws);
  // The surface images (96 x 96 x 2 doubles, 147 KB each) are recipes, not points.
  CHECK(bytes.size() < 8000);
  MESSAGE("journal of ", j.steps().size(), " steps on the disk: ", bytes.size(), " bytes");
  Journal back = disk::decode_journal(bytes, ws);
  REQUIRE(back.steps().size() == j.steps().size());
  CHECK(back.position() == j.position());
  for (std::size_t k = 0; k < j.steps().size(); ++k)
    CHECK(back.steps()[k].name == j.steps()[k].name);

  // Every state comes back, images made again bit for bit.
  Workspace w = ws;
  std::size_t state = back.position();
  test::check_same_workspace(w, states[state]);
  while (back.undo(w)) {
    --state;
    CAPTURE(state);
    test::check_same_workspace(w, states[state]);
  }
  CHECK(state == 0);
  while (back.redo(w)) ++state;
  CHECK(state == states.size() - 1);
  test::check_same_workspace(w, states.back());
  // The images made again are recipes again: saved once more, the same bytes.
  for (std::size_t k = 0; k < 2; ++k) back.undo(w);
  CHECK(disk::encode_journal(back, w) == bytes);
}

TEST_CASE("a crafted journal is refused with the reason") {
  Workspace ws = test::make_interpolated(4, 5, 2, 2);
  saved(ws);
  Journal j(ws);
  command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 2, 9); });
  command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 5, 9); });
  j.undo(ws);
  saved(ws);
  const std::string good = disk::encode_journal(j, ws);
  CHECK_NOTHROW(disk::decode_journal(good, ws));

  auto refused = [&](auto craft) {
    Journal copy = j;
    craft(copy.steps_to_complete());
    const std::string bytes = disk::encode_journal(copy, ws);
    try {
      disk::decode_journal(bytes, ws);
    } catch (const disk::Damage& d) {
      return std::string(d.reason());
    }
    return std::string("ACCEPTED");
  };
  using Steps = std::span<JournalStep>;
  // Values before a step that are not those of the state it starts from.
  CHECK(refused([](Steps s) { s[0].inppn.after[0] += 1; }) == "JOURNAL: STEPS DO NOT FOLLOW");
  CHECK(refused([](Steps s) { s[1].inppn.before[1] += 1; }) == "JOURNAL: STEPS DO NOT FOLLOW");
  // A range outside INPPN.
  CHECK(refused([](Steps s) {
          s[0].inppn.ranges[0] = {1000000, 1000003};
        }) == "JOURNAL: STEPS DO NOT FOLLOW");
  // A state the workspace would refuse: a number that is not finite, NOCUR out of range.
  CHECK(refused([](Steps s) {
          s[0].inppn.before[0] = std::numeric_limits<double>::infinity();
        }).starts_with("JOURNAL: "));
  CHECK(refused([](Steps s) { s[0].after.nocur = 5; }) == "JOURNAL: STEPS DO NOT FOLLOW");
  CHECK(refused([](Steps s) { s[0].before.status[0] = 7; }).starts_with("JOURNAL: STATUS"));
  // A name that is not a command's words (it is printed on the terminal).
  CHECK(refused([](Steps s) { s[0].name = "\x1b[2J"; }) == "FORMAT");
  // Bytes cut short or run on.
  CHECK_THROWS_AS(disk::decode_journal(good.substr(0, good.size() - 1), ws), disk::Damage);
  CHECK_THROWS_AS(disk::decode_journal(good + "x", ws), disk::Damage);
  // Read with a workspace it was not saved with.
  Workspace other = ws;
  change_point(other, 2, 100);
  CHECK_THROWS_AS(disk::decode_journal(good, other), disk::Damage);
}

TEST_CASE("the session keeps the journal: read back at start, a damaged one refused alone") {
  test::TempDir dir;
  Disk disk(dir.path());
  Workspace ws = test::make_interpolated(6, 6, 1, 1);
  std::vector<Workspace> states;
  {
    Session session(disk);
    Workspace loaded = session.load();
    Journal j = session.take_journal(loaded);
    CHECK(j.undo_count() == 0);
    j = Journal(loaded);
    CHECK(j.record(ws, "BUILD"));
    session.save(ws, &j);
    states.push_back(ws);
    command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 4, 3); });
    session.save(ws, &j);
  }
  {
    Session session(disk);
    Workspace loaded = session.load();
    CHECK(session.notices().empty());
    Journal j = session.take_journal(loaded);
    CHECK(j.undo_count() == 2);
    CHECK(j.undo(loaded) == "CHANGE POINTS");
    test::check_same_workspace(loaded, states[0]);
    session.save(loaded, &j);
  }
  // The journal rewritten with a value that does not fit, the file framed again: a crafted
  // session whose checksum holds.
  const fs::path file = dir.path() / "BINSAVE.IGDSCONT";
  const std::string framed = test::read_file(file);
  auto table = disk::decode_session(disk::unframe("IGDSCONT", framed).payload);
  REQUIRE(!table.journal.empty());
  {
    Session session(disk);
    Workspace loaded = session.load();
    Journal j = session.take_journal(loaded);
    REQUIRE(j.redo_count() == 1);
    j.steps_to_complete()[1].inppn.before[0] += 0.5;
    table.journal = disk::encode_journal(j, loaded);
  }
  test::rewrite_file(file, disk::frame("IGDSCONT", disk::encode_session(table), 2));
  {
    Session session(disk);
    Workspace loaded = session.load();
    REQUIRE(session.notices().size() == 1);
    CHECK(session.notices()[0] ==
          "UNDO JOURNAL IN BINSAVE.IGDSCONT DAMAGED (JOURNAL: STEPS DO "
          "NOT FOLLOW): NOTHING TO UNDO");
    // The workspace itself is kept.
    test::check_same_workspace(loaded, states[0]);
    Journal j = session.take_journal(loaded);
    CHECK(j.undo_count() + j.redo_count() == 0);
    // The next save writes the session without it, though nothing else changed.
    session.save(loaded, &j);
  }
  Session session(disk);
  session.load();
  CHECK(session.notices().empty());
}

TEST_CASE("an image the session keeps by its recipe is not made to be put in the journal") {
  test::TempDir dir;
  Disk disk(dir.path());
  Workspace ws = test::make_interpolated(6, 6, 2, 2);
  const Description desim{1, Projection::isometric, {3, 30, 0}};
  {
    Session session(disk);
    Workspace loaded = session.load();
    Journal j = session.take_journal(loaded);
    ws.image = std::make_shared<const Image>(image_of(ws, desim));
    CHECK(j.record(ws, "DISPLAY SURFACE"));
    session.save(ws, &j);
  }
  Session session(disk);
  Workspace loaded = session.load();
  Journal j = session.take_journal(loaded);
  // Read back as the recipe, made when first looked at: its recipe is known before.
  REQUIRE(loaded.image);
  const ImageRef before = loaded.image;
  CHECK_FALSE(before.made());
  REQUIRE(before.recipe());
  CHECK(before.recipe()->second == desim);
  CHECK(j.recipe_of(before) == before.recipe());
  CHECK_FALSE(before.made());
  // A CHANGE, then a DISPLAY replaces it: the step keeps it and the session is saved with the
  // journal, all without making it (which means interpolating the surface it was drawn from
  // again: at 4 M points, most of a second).
  command(j, loaded, "CHANGE POINTS", [&] { change_point(loaded, 7, 4); });
  session.save(loaded, &j);
  command(j, loaded, "DISPLAY SURFACE",
          [&] { loaded.image = std::make_shared<const Image>(image_of(loaded, desim)); });
  session.save(loaded, &j);
  CHECK_FALSE(before.made());
  // UNDO gives it back, the same image as drawn before.
  CHECK(j.undo(loaded) == "DISPLAY SURFACE");
  CHECK(loaded.image == before);
  CHECK(*loaded.image == *ws.image);
  CHECK(before.made());
}

TEST_CASE("a journal damaged at random is refused or gives states the workspace accepts") {
  Workspace ws = test::make_interpolated(5, 4, 1, 2);
  saved(ws);
  Journal j(ws);
  command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 3, 2); });
  command(j, ws, "DISPLAY SURFACE", [&] {
    ws.image = std::make_shared<const Image>(image_of(ws, {1, Projection::orthogonal, {1, 0, 0}}));
  });
  command(j, ws, "DISPLAY FILE", [&] {
    ws.temp2 = std::make_shared<const Image>(test::make_image(0, Projection::conic, 2, 2, 4));
  });
  command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 7, -2); });
  j.undo(ws);
  saved(ws);
  const std::string good = disk::encode_journal(j, ws);
  std::mt19937 random(14);
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string bytes = good;
    const int flips = 1 + trial % 3;
    for (int f = 0; f < flips; ++f)
      bytes[random() % bytes.size()] = static_cast<char>(random() % 256);
    if (trial % 7 == 0) bytes.resize(random() % bytes.size());
    std::optional<Journal> back;
    try {
      back = disk::decode_journal(bytes, ws);
    } catch (const disk::Damage&) {
      continue;
    }
    ++accepted;
    // Every state it holds is one the workspace accepts, its images drawn or refused in words.
    Workspace w = ws;
    auto look = [&] {
      CHECK(!surface_problem(w, false));
      for (const ImageRef* image : {&w.image, &w.temp1, &w.temp2}) {
        try {
          // Made here, outside CHECK: a view the kernels refuse is a DataError, worded by
          // the command that shows the image (as for the session's own recipes).
          if (!*image) continue;
          const Image& made = **image;
          CHECK(!image_problem(made));
        } catch (const DataError&) {
        }
      }
    };
    try {
      while (back->undo(w)) look();
      while (back->redo(w)) look();
    } catch (const DataError&) {
    }
  }
  MESSAGE(accepted, " of 3000 damaged journals accepted, every state checked");
}

TEST_CASE("a surface replaced whole (RESTORE) keeps the parts that differ, or both whole") {
  Workspace ws = test::make_interpolated(30, 30, 0, 0);
  saved(ws);
  Journal j(ws);
  const Workspace before = ws;
  // The same shapes, three values apart: three short ranges, not 2 x 21.6 KB.
  CHECK(command(j, ws, "RESTORE", [&] {
    ws.inppn.ravel[10] = 1;
    ws.inppn.ravel[14] = 2;  // within 8 of the first: one range
    ws.inppn.ravel[2000] = 3;
    ws.changes.replaced();
  }));
  const JournalStep& step = j.steps().back();
  CHECK(!step.inppn.whole);
  CHECK(step.inppn.ranges ==
        std::vector<std::pair<std::size_t, std::size_t>>{{10, 15}, {2000, 2001}});
  CHECK(step.inptg.unchanged());
  const Workspace restored = ws;
  // Most values changed: both arrays whole.
  CHECK(command(j, ws, "RESTORE", [&] {
    for (double& v : ws.inppn.ravel) v += 1;
    ws.changes.replaced();
  }));
  CHECK(j.steps().back().inppn.whole);
  // The same surface again: no step.
  CHECK_FALSE(command(j, ws, "RESTORE", [&] { ws.changes.replaced(); }));
  // (The test changed the inputs alone; UNDO interpolates them again.)
  j.undo(ws);
  CHECK(test::same_bits(ws.inppn, restored.inppn));
  CHECK(test::same_bits(ws.inptg, restored.inptg));
  j.undo(ws);
  test::check_same_surface(ws, before);
}

TEST_CASE("UNDO and REDO make PATCHES and INTPN again with the twists of the state they go to") {
  Workspace ws = test::make_interpolated(5, 6, 2, 3);
  saved(ws);
  Journal j(ws);
  const Workspace zero = ws;
  // PATCHES and INTPN of the inputs and twists `ws` has now, as the commands make them.
  auto interpolated = [&ws] {
    Surface s = interpolate(surface_input(ws));
    ws.patches = std::move(s.patches);
    ws.intpn = std::move(s.intpn);
  };
  // CHANGE TWISTS MARKS: the same points, Marks's twists, STATUS[3] = 1.
  CHECK(command(j, ws, "CHANGE TWISTS", [&] {
    ws.status[Workspace::status_twists] = 1;
    interpolated();
  }));
  const Workspace marks = ws;
  REQUIRE(marks.patches != zero.patches);
  CHECK(command(j, ws, "CHANGE POINTS", [&] {
    change_point(ws, 7, 4, false);
    interpolated();
  }));
  const Workspace changed = ws;
  CHECK(j.undo(ws) == "CHANGE POINTS");
  test::check_same_workspace(ws, marks);
  CHECK(j.undo(ws) == "CHANGE TWISTS");
  test::check_same_workspace(ws, zero);
  CHECK(j.redo(ws) == "CHANGE TWISTS");
  test::check_same_workspace(ws, marks);
  CHECK(j.redo(ws) == "CHANGE POINTS");
  test::check_same_workspace(ws, changed);
}

TEST_CASE("an UNDO whose state does not interpolate leaves PATCHES and INTPN as they were") {
  // A state whose point is not finite (the APL environment can assign one to INPPN; the
  // interpolation refuses it), then a command that mends it: UNDO to that state is refused with
  // the kernel's DataError, and the surface shown stays the mended one, bit for bit.
  Workspace ws = test::make_interpolated(5, 6, 2, 3);
  saved(ws);
  Journal j(ws);
  CHECK(command(j, ws, "APL", [&] { change_point(ws, 8, std::nan(""), false); }));
  CHECK(command(j, ws, "CHANGE POINTS", [&] { change_point(ws, 8, 2.5); }));
  const Workspace mended = ws;
  try {
    j.undo(ws);
    FAIL("the state was not refused");
  } catch (const DataError& e) {
    CHECK(e.problem == DataError::Problem::point_not_finite);
  }
  CHECK(ws.patches == mended.patches);
  CHECK(ws.intpn == mended.intpn);
  CHECK(ws.inppn == mended.inppn);
}

TEST_CASE("an UNDO whose state overflows is refused, PATCHES and INTPN as they were bit for bit") {
  // A state whose tangent is finite but so large that its patches are not (read from a forged
  // journal, or left by END APL): the interpolation into the workspace's own arrays is refused
  // after it wrote them, and they are made again as they were.
  Workspace ws = test::make_interpolated(5, 6, 2, 3);
  saved(ws);
  Journal j(ws);
  CHECK(command(j, ws, "APL", [&] {
    ws.inptg.ravel[0] = 1e308;
    ws.changes.edited(Edits::none(), [] {
      Edits e = Edits::none();
      e.part(0, 4);
      return e;
    }());
  }));
  CHECK(command(j, ws, "CHANGE TANGENTS", [&] {
    ws.inptg.ravel[0] = 1;
    Edits e = Edits::none();
    e.part(0, 4);
    ws.changes.edited(Edits::none(), e);
    Surface s = interpolate(surface_input(ws));
    ws.patches = std::move(s.patches);
    ws.intpn = std::move(s.intpn);
  }));
  const Workspace mended = ws;
  try {
    j.undo(ws);
    FAIL("the state was not refused");
  } catch (const DataError& e) {
    CHECK(e.problem == DataError::Problem::patch_not_finite);
    CHECK(e.number == 1);
  }
  test::check_same_surface(ws, mended);
  CHECK(j.undo_count() == 2);
}

TEST_CASE("UNDO and REDO of a step that left the surface as it was keep PATCHES and INTPN") {
  Workspace ws = test::make_interpolated(5, 6, 2, 3);
  saved(ws);
  Journal j(ws);
  const ImageRef first = ws.image;
  CHECK(command(j, ws, "DISPLAY SURFACE", [&] {
    ws.image = std::make_shared<const Image>(image_of(ws, {1, Projection::isometric, {3, 30, 0}}));
  }));
  CHECK(command(j, ws, "HELP SHORT", [&] { ws.status[0] = 0; }));
  const Workspace after = ws;
  // Not made again: the very arrays stay, and the inputs with them (PATCHES are not kept).
  REQUIRE(ws.patches.empty());
  const double* intpn = ws.intpn.data();
  const double* inppn = ws.inppn.data();
  for (const char* name : {"HELP SHORT", "DISPLAY SURFACE"}) CHECK(j.undo(ws) == name);
  CHECK(ws.image == first);
  CHECK(ws.patches.empty());
  CHECK(ws.intpn.data() == intpn);
  CHECK(ws.inppn.data() == inppn);
  CHECK(j.redo(ws) == "DISPLAY SURFACE");
  CHECK(j.redo(ws) == "HELP SHORT");
  test::check_same_workspace(ws, after);
  CHECK(ws.intpn.data() == intpn);
  // PATCHES of the user's own (END APL, no step of their own) are made again from the inputs by an
  // UNDO, as by any.
  test::own_surface(ws);
  ws.patches.ravel[0] += 1;
  CHECK_FALSE(j.record(ws, "APL"));
  CHECK(j.undo(ws) == "HELP SHORT");
  CHECK(ws.changes.derived);
  CHECK(ws.patches.empty());
  CHECK(test::same_patches(ws, after));
  CHECK(ws.intpn == after.intpn);
}
