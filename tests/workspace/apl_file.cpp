// END APL's own workspace on the disk (workspace/disk/apl_file.h): the user's functions and
// variables in the session and in NAME.IGDSAPLW, bit for bit; files forged with valid frames and
// checksums refused, each for its reason, before anything of the size they claim is made.
#include "workspace/disk/apl_file.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "tests/workspace/forge.h"
#include "workspace/disk/session.h"
#include "workspace/disk/session_file.h"
#include "workspace/error.h"

namespace igds::test {

namespace {

std::vector<AplVariable> some_variables() {
  AplVariable a{"A", {2, 3}, false, {1, -0.0, 3.5, 1e300, 5e-324, -6}, {}};
  AplVariable e{"E", {0, 4}, true, {}, {}};
  AplVariable t{
      "T\xE2\x88\x86"
      "1",
      {4},
      true,
      {},
      U"⍴A b"};
  AplVariable s{"Z_", {}, false, {42}, {}};
  return {a, e, t, s};
}

const std::vector<std::vector<std::string>> some_functions = {{"Z←F X", "Z←X×2"},
                                                              {"G", "'⍝ ¯1'", "→0"}};

// One variable as write_variables writes it, with any field forged.
struct Forged {
  std::string name = "A";
  std::uint8_t kind = 0;
  std::vector<std::uint64_t> shape;
  std::vector<double> numbers{1};
  std::vector<std::uint32_t> characters;
  void write(disk::Writer& w) const {
    w.u32(static_cast<std::uint32_t>(name.size()));
    w.bytes(name);
    w.u8(kind);
    w.u32(static_cast<std::uint32_t>(shape.size()));
    for (auto d : shape) w.u64(d);
    for (double x : numbers) w.f64(x);
    for (auto c : characters) w.u32(c);
  }
};

// The report of )LOAD for a NAME.IGDSAPLW whose payload is `payload` (framed and summed as igds
// frames a file: only the meaning is wrong).
std::string loaded(const Disk& disk, const std::string& payload) {
  const auto path = disk.path("W", "IGDSAPLW");
  std::filesystem::remove(path);
  write_file(path, disk::frame("IGDSAPLW", payload));
  try {
    disk::load_apl_workspace(disk, "W");
  } catch (const Report& r) {
    return r.what();
  }
  return "(loaded)";
}

std::string with_variables(const std::vector<Forged>& vars, std::uint32_t count = 0) {
  disk::Writer w;
  w.u8(0);
  w.u32(0);  // no functions
  w.u32(count ? count : static_cast<std::uint32_t>(vars.size()));
  for (const auto& v : vars) v.write(w);
  return w.str();
}

std::string refused(std::string_view reason) {
  return fmt::format("FILE DAMAGED: W.IGDSAPLW (FORMAT: {}); NOTHING LOADED", reason);
}

}  // namespace

TEST_CASE("the user's variables and functions, written and read back bit for bit") {
  disk::Writer w;
  disk::write_functions(w, some_functions);
  disk::write_variables(w, some_variables());
  const std::string bytes = w.str();
  disk::Reader r(bytes);
  CHECK(disk::read_functions(r) == some_functions);
  const auto back = disk::read_variables(r);
  CHECK(r.at_end());
  REQUIRE(back == some_variables());
  CHECK(std::signbit(back[0].numbers[1]));
  // stored_bytes is what write_variables takes (the session's bound is counted with it).
  disk::Writer variables;
  disk::write_variables(variables, some_variables());
  std::size_t sizes = 4;  // the count
  for (const auto& v : some_variables())
    sizes += disk::stored_bytes(v.name.size(), v.shape.size(),
                                v.characters ? v.text.size() : v.numbers.size(), v.characters);
  CHECK(sizes == variables.size());
  // In the session file: a section of its own, before the journal's.
  disk::SessionTable t;
  t.apl_variables = some_variables();
  t.functions = some_functions;
  t.journal = "J";
  const auto decoded = disk::decode_session(disk::encode_session(t));
  CHECK(decoded.apl_variables == t.apl_variables);
  CHECK(decoded.functions == t.functions);
  CHECK(decoded.journal == "J");
  CHECK(decoded.apl_variables_damage.empty());
}

TEST_CASE("NAME.IGDSAPLW: written whole, read back; missing or damaged, a report") {
  TempDir dir;
  const Disk disk(dir.path());
  disk::AplWorkspace ws{true, some_functions, some_variables()};
  disk::save_apl_workspace(disk, "WS1", ws);
  auto back = disk::load_apl_workspace(disk, "WS1");
  CHECK(back.surface);
  CHECK(back.functions == some_functions);
  CHECK(back.variables == some_variables());
  // Replaced whole, and nothing left beside it.
  ws.surface = false;
  ws.variables.pop_back();
  disk::save_apl_workspace(disk, "WS1", ws);
  back = disk::load_apl_workspace(disk, "WS1");
  CHECK(!back.surface);
  CHECK(back.variables == ws.variables);
  CHECK(std::distance(std::filesystem::directory_iterator(dir.path()),
                      std::filesystem::directory_iterator()) == 1);

  CHECK_THROWS_WITH_AS(disk::load_apl_workspace(disk, "NONE"), "FILE NOT FOUND", Report);
  std::string bytes = read_file(disk.path("WS1", "IGDSAPLW"));
  bytes[40] ^= 1;
  rewrite_file(disk.path("WS1", "IGDSAPLW"), bytes);
  CHECK_THROWS_WITH_AS(disk::load_apl_workspace(disk, "WS1"),
                       "FILE DAMAGED: WS1.IGDSAPLW (CHECKSUM); NOTHING LOADED", Report);
  CHECK_THROWS_WITH_AS(disk::load_apl_workspace(disk, "WS1", "NOTHING COPIED"),
                       "FILE DAMAGED: WS1.IGDSAPLW (CHECKSUM); NOTHING COPIED", Report);
  // Never written through a link: the link is replaced, its target untouched.
  write_file(dir.path() / "target", "mine");
  std::filesystem::create_symlink(dir.path() / "target", disk.path("LINKED", "IGDSAPLW"));
  disk::save_apl_workspace(disk, "LINKED", ws);
  CHECK(read_file(dir.path() / "target") == "mine");
  CHECK(!std::filesystem::is_symlink(disk.path("LINKED", "IGDSAPLW")));
  CHECK(disk::load_apl_workspace(disk, "LINKED").variables == ws.variables);
}

TEST_CASE("a forged NAME.IGDSAPLW: each refusal says its reason, nothing huge is made") {
  TempDir dir;
  const Disk disk(dir.path());
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(loaded(disk, with_variables({Forged{}})) == "(loaded)");
  // The workspace's own framing.
  {
    disk::Writer w;
    w.u8(2);
    w.u32(0);
    w.u32(0);
    CHECK(loaded(disk, w.str()) == refused("NEITHER WITH NOR WITHOUT A SURFACE"));
  }
  CHECK(loaded(disk, with_variables({}) + "x") == refused("BYTES AFTER THE VARIABLES"));
  // The functions.
  {
    disk::Writer w;
    w.u8(0);
    w.u32(0xFFFFFFFF);
    CHECK(loaded(disk, w.str() + std::string(64, '\0')) ==
          refused("MORE FUNCTIONS THAN THE FILE HOLDS"));
    disk::Writer none;
    none.u8(0);
    none.u32(1);
    none.u32(0);
    none.u32(0);
    CHECK(loaded(disk, none.str() + std::string(8, '\0')) ==
          refused("A FUNCTION WITHOUT LINES OR WITH MORE THAN THE FILE HOLDS"));
  }
  // The variables.
  CHECK(loaded(disk, with_variables({}, 0xFFFFFFFF)) ==
        refused("MORE VARIABLES THAN THE FILE HOLDS"));
  for (const char* name : {"2A", "a", "A B", "", "A\xE2\x88", "\xE2\x8D\xBA"}) {
    CAPTURE(name);
    Forged v;
    v.name = name;
    CHECK(loaded(disk, with_variables({v})) == refused("A VARIABLE'S NAME THAT IS NO APL NAME"));
  }
  {
    Forged v;
    v.name = std::string(3000, 'A');  // APL's names have no limit of length
    CHECK(loaded(disk, with_variables({v})) == "(loaded)");
    v.name = "INPPN";
    CHECK(loaded(disk, with_variables({v})) == refused("INPPN IS AN IGDS VARIABLE"));
  }
  {
    Forged a, b;
    b.name = "B";
    CHECK(loaded(disk, with_variables({b, a})) == refused("VARIABLES OUT OF ORDER OR TWICE"));
    CHECK(loaded(disk, with_variables({a, a})) == refused("VARIABLES OUT OF ORDER OR TWICE"));
  }
  {
    Forged v;
    v.kind = 2;
    CHECK(loaded(disk, with_variables({v})) ==
          refused("A VARIABLE NEITHER OF NUMBERS NOR OF CHARACTERS"));
  }
  {
    Forged v;
    v.shape.assign(9, 1);
    CHECK(loaded(disk, with_variables({v})) == refused("A VARIABLE OF RANK ABOVE 8"));
  }
  {
    // Shapes whose product the bytes cannot hold, or overflows: refused before any allocation.
    Forged v;
    v.numbers.clear();
    for (auto shape : {std::vector<std::uint64_t>{std::uint64_t(1) << 31, std::uint64_t(1) << 31},
                       {std::uint64_t(1) << 52, 4},
                       {2}}) {
      v.shape = shape;
      CHECK(loaded(disk, with_variables({v})) == refused("A VARIABLE LARGER THAN THE FILE HOLDS"));
    }
    v.shape = {3, 0, (std::uint64_t(1) << 53) + 1, 2};
    CHECK(loaded(disk, with_variables({v})) == refused("AN AXIS LONGER THAN 2*53"));
    v.shape = {std::uint64_t(1) << 53, 0};  // empty: legal (0 3E9⍴0 is an APL array)
    CHECK(loaded(disk, with_variables({v})) == "(loaded)");
  }
  for (double x : {inf, -inf, std::nan("")}) {
    Forged v;
    v.numbers = {x};
    CHECK(loaded(disk, with_variables({v})) == refused("A NUMBER THAT IS NOT FINITE"));
  }
  for (std::uint32_t c : {0xD800u, 0xDFFFu, 0x110000u, 0xFFFFFFFFu}) {
    Forged v;
    v.kind = 1;
    v.shape = {1};
    v.numbers.clear();
    v.characters = {c};
    CHECK(loaded(disk, with_variables({v})) == refused("A CHARACTER THAT IS NO UNICODE CHARACTER"));
  }
  // Cut anywhere: a report, never a crash.
  const std::string good = with_variables({Forged{}});
  for (std::size_t n = 0; n < good.size(); ++n)
    CHECK(loaded(disk, good.substr(0, n)).starts_with("FILE DAMAGED: W.IGDSAPLW ("));
}

TEST_CASE("END APL's variables forged in the session cost themselves alone") {
  TempDir dir;
  const Disk disk(dir.path());
  Workspace ws = make_workspace(3, 3, 1, 1);
  ws.functions = some_functions;
  ws.apl_variables = some_variables();
  {
    Session session(disk);
    session.load();
    session.save(ws);
  }
  // The section as a forger writes it: the session's other parts, framed and summed, intact.
  auto forged_session = [&](const std::string& section) {
    disk::SessionTable t = forge::session_table(disk);
    t.apl_variables.clear();
    std::string payload = disk::encode_session(t);
    disk::Writer w;
    w.u32(0x564c5041);  // "APLV"
    w.u64(section.size());
    w.bytes(section);
    payload += w.str();
    std::filesystem::remove(forge::session_path(disk));
    write_file(forge::session_path(disk), disk::frame("IGDSCONT", payload, 2));
  };
  auto section = [](const std::vector<Forged>& vars) {
    disk::Writer w;
    w.u32(static_cast<std::uint32_t>(vars.size()));
    for (const auto& v : vars) v.write(w);
    return w.str();
  };
  Forged bad;
  bad.numbers = {std::nan("")};
  forged_session(section({bad}));
  {
    Session session(disk);
    Workspace back = session.load();
    REQUIRE(session.notices().size() == 1);
    CHECK(session.notices()[0] ==
          "END APL'S VARIABLES IN BINSAVE.IGDSCONT DAMAGED (FORMAT: A NUMBER THAT IS NOT "
          "FINITE): THE SESSION FILE KEPT AS BINSAVE.IGDSBAD; THEY START EMPTY");
    CHECK(back.apl_variables.empty());
    CHECK(back.functions == some_functions);
    check_same_surface(back, ws);
    // The copy kept aside is the forged file, whole; the next save writes the session without
    // the section, even with nothing else changed.
    CHECK(disk::unframe("IGDSCONT", read_file(dir.path() / "BINSAVE.IGDSBAD"))
              .payload.ends_with(section({bad})));
    session.save(back);
  }
  {
    Session session(disk);
    session.load();
    CHECK(session.notices().empty());
  }
  // Trailing bytes and a section larger than igds writes.
  forged_session(section({Forged{}}) + "x");
  {
    Session session(disk);
    CHECK(session.load().functions == some_functions);
    REQUIRE(session.notices().size() == 1);
    CHECK(session.notices()[0] ==
          "END APL'S VARIABLES IN BINSAVE.IGDSCONT DAMAGED (FORMAT: BYTES AFTER THE VARIABLES): "
          "THE SESSION FILE KEPT AS BINSAVE1.IGDSBAD; THEY START EMPTY");
  }
  forged_session(section({Forged{}}) + std::string(disk::max_session_apl_bytes, '\0'));
  {
    Session session(disk);
    session.load();
    REQUIRE(session.notices().size() == 1);
    CHECK(session.notices()[0].starts_with(
        "END APL'S VARIABLES IN BINSAVE.IGDSCONT DAMAGED (FORMAT: MORE THAN 8 MB)"));
  }
}

}  // namespace igds::test
