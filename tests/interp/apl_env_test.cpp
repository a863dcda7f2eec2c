// END APL: an APL\360 session on the workspace (interp/apl_env.h): the IGDS globals read and
// assigned, checked at once for their kind and at START against each other, PATCHES and INTPN
// made again from changed inputs, and the manual's functions calling igds's own code.
#include "interp/apl_env.h"

#include <doctest/doctest.h>

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <limits>

#include "commands/command.h"
#include "interp/apl/format.h"
#include "tests/workspace/disk_fixtures.h"
#include "workspace/disk/disk.h"
#include "workspace/kernels/spline.h"
#include "workspace/kernels/surface.h"

namespace igds::test {

using Lines = std::vector<std::string>;

namespace {

// An environment on `ws` that keeps what it says, reports and runs.
struct Apl {
  Workspace ws;
  Lines said, reported, input;
  std::vector<Lines> commands;
  int session_saves = 0, shown = 0;
  std::optional<Workspace> saved_session;
  std::vector<Picture> drawn, plotted;
  std::function<void(const Lines&)> run;  // what a command does, when it matters
  const Disk* disk = nullptr;
  AplEnvironment env;
  explicit Apl(Workspace w, const Disk* d = nullptr)
      : ws(std::move(w)), disk(d), env(ws, hooks()) {}
  AplEnvironment::Hooks hooks() {
    AplEnvironment::Hooks h;
    h.say = [this](std::string_view l) { said.emplace_back(l); };
    h.report = [this](std::string_view l) { reported.emplace_back(l); };
    h.document = [this](std::string_view t) { said.emplace_back(t); };
    h.read = [this](std::string_view) -> std::optional<std::string> {
      if (input.empty()) return std::nullopt;
      std::string line = input.front();
      input.erase(input.begin());
      return line;
    };
    h.command = [this](const Lines& words) {
      commands.push_back(words);
      if (run) run(words);
      return true;
    };
    h.save_session = [this] {
      ++session_saves;
      return std::string();
    };
    h.load_session = [this]() -> std::optional<Workspace> { return saved_session; };
    h.show = [this](const ImageRef&) { ++shown; };
    h.draw = [this](const Picture& p, std::string_view line) {
      drawn.push_back(p);
      said.emplace_back(line);
    };
    h.plot = [this](const Picture& p) { plotted.push_back(p); };
    h.disk = disk;
    return h;
  }
  // The lines printed for one typed line (reports included, in order after what was said).
  Lines operator()(std::string_view line) {
    said.clear();
    reported.clear();
    env.execute(line);
    Lines out = reported;
    out.insert(out.end(), said.begin(), said.end());
    return out;
  }
};

// A surface with no images, STATUS as at the first start.
Workspace surface(int nocur, int nostr, int intcu, int intst) {
  Workspace ws = make_interpolated(nocur, nostr, intcu, intst);
  ws.image.reset();
  ws.temp1.reset();
  ws.temp2.reset();
  ws.status = {1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  return ws;
}

}  // namespace

TEST_CASE("the workspace variables are APL variables") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("NOCUR") == Lines{"3"});
  CHECK(apl("NOCUR×NOSTR") == Lines{"6"});
  CHECK(apl("⍴INPPN") == Lines{"6 3"});
  CHECK(apl("⍴⍴PATCHES") == Lines{"5"});
  CHECK(apl("⍴INTPN") == Lines{"5 3 3"});
  CHECK(apl("2+2") == Lines{"4"});
  CHECK(apl("INPPN[1;]") == Lines{"0 0 0"});
  CHECK(apl("STATUS") == Lines{"1 0 0 0 0 0 0 0 0 0"});
  CHECK(apl("X←5") == Lines{});
  CHECK(apl("X×NOCUR") == Lines{"15"});
  CHECK(apl("IMAGE").at(0) == "VALUE ERROR");
  CHECK(apl(")VARS") ==
        Lines{"X", "IGDS: INPPN INPTG INTCU INTPN INTST NOCUR NOSTR PATCHES STATUS"});
  // The workspace's own functions, under their heading: every function of the manual's
  // section 7 (IGDS4013 and the functions common to both workspaces).
  std::string fns;
  for (const auto& line : apl(")FNS")) fns += line + " ";
  for (const char* name :
       {"ALFINP",  "ASSON",  "AUTOMSAVE",  "CHGRID",  "CHPOINT", "CHTANG", "COEFFICIENTI", "COMBUI",
        "COMCHA",  "COMDIS", "COMEND",     "COMPLO",  "COMRES",  "COMSAV", "COMSTO",       "COMWRI",
        "CONIC",   "COONS",  "CURVILINEO", "DEFVAR",  "DESCR",   "DISPLA", "DISTA",        "EXPL",
        "EXPLONG", "F0",     "F1",         "FIT",     "G0",      "G1",     "GETCOM",       "INIT",
        "ISOM",    "LUT",    "NOTO",       "NUMINP",  "ORTHOG",  "OUT",    "PARBU",        "PARCH",
        "PARDI",   "PAREN",  "PARPL",      "PARRE",   "PARSA",   "PARST",  "PARWR",        "PLOTG",
        "PLOTHP",  "PLOTP",  "PLOTV",      "PROSPAR", "RESTORE", "SCALE",  "START",        "STATE",
        "TEKC",    "TEKG",   "TEKP",       "TEKV",    "TKX",     "WRT"}) {
    CAPTURE(name);
    CHECK(fns.find(std::string(" ") + name + " ") != std::string::npos);
  }
  CHECK(fns.starts_with("IGDS: ALFINP "));
}

TEST_CASE("an assignment of the wrong kind is refused at once; what came before it stays") {
  Apl apl(surface(3, 2, 1, 1));
  const Workspace before = apl.ws;
  CHECK(apl("NOCUR←'A'").at(0) == "DOMAIN ERROR");
  CHECK(apl("NOCUR←1 2").at(0) == "LENGTH ERROR");
  CHECK(apl("NOCUR←2.5").at(0) == "DOMAIN ERROR");
  CHECK(apl("INPPN←5").at(0) == "RANK ERROR");
  CHECK(apl("STATUS←1 2 3").at(0) == "LENGTH ERROR");
  CHECK(apl("DESIM←1 3 3 30 0").at(0) == "VALUE ERROR");  // no image to describe
  CHECK(apl.ws == before);
  // An assignment made before the failure is made (APL\360).
  CHECK(apl("Y←(INTCU←4)+'A'").at(0) == "DOMAIN ERROR");
  CHECK(apl.ws.intcu == 4);
  CHECK(!apl.env.start());
}

TEST_CASE("PATCHES in END APL are the surface's before an input changed, until START") {
  Apl apl(surface(3, 3, 1, 1));
  REQUIRE(apl.ws.patches.empty());  // the interpolation's: made when read
  const Array before = interpolate(surface_input(apl.ws)).patches;
  CHECK(apl("INPPN[5;3]←7").empty());
  CHECK(apl.ws.patches == before);
  // The corner of patch (2, 2) is point 5 as it was.
  CHECK(apl("PATCHES[2;2;3;1;1]=7") == Lines{"0"});
  REQUIRE(!apl.env.start());
  CHECK(apl("PATCHES[2;2;3;1;1]") == Lines{"7"});
  // Made again from the new inputs, and not kept.
  CHECK(apl.ws.changes.derived);
  CHECK(apl.ws.patches.empty());
  CHECK(given_patches(apl.ws) == interpolate(surface_input(apl.ws)).patches);
  CHECK(given_patches(apl.ws) != before);
  CHECK(apl("INTPN[3;3;3]") == Lines{"7"});
}

TEST_CASE("START makes PATCHES and INTPN again from changed inputs") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("INPPN[5;3]←2.5").empty());
  CHECK(apl.ws.inppn.ravel[3 * 4 + 2] == 2.5);
  CHECK(apl("INTCU←2").empty());
  REQUIRE(!apl.env.start());
  const Surface expected = interpolate({3, 2, 2, 1, &apl.ws.inppn, &apl.ws.inptg});
  CHECK(given_patches(apl.ws) == expected.patches);
  CHECK(apl.ws.intpn == expected.intpn);
  CHECK(apl.ws.changes.derived);
  // The tangents the interpolation made are kept with the surface (as BUILD's are).
  test::check_kept_splines(apl.ws);
  CHECK(apl("⍴INTPN") == Lines{"7 3 3"});
  // FIT is the grid of the current PATCHES, as igds computes it.
  CHECK(apl("∧/,FIT=INTPN") == Lines{"1"});
}

TEST_CASE("STATUS[3] and STATUS[4] assigned change the surface: other twists make PATCHES again") {
  Apl apl(surface(5, 6, 2, 3));
  const Workspace zero = apl.ws;
  // Marks's twists: PATCHES and INTPN made again with them, and a surface of its own (an image
  // drawn before is not of it: the session keeps it by the surface it was drawn from).
  CHECK(apl("STATUS[3]←1").empty());
  REQUIRE(!apl.env.start());
  const Surface marks = interpolate(surface_input(apl.ws));
  CHECK(given_patches(apl.ws) == marks.patches);
  CHECK(apl.ws.intpn == marks.intpn);
  CHECK(given_patches(apl.ws) != given_patches(zero));
  CHECK(apl.ws.changes.derived);
  CHECK(apl.ws.changes.surface != zero.changes.surface);
  // The AUTO mark: the same PATCHES, another surface.
  std::uint64_t generation = apl.ws.changes.surface;
  CHECK(apl("STATUS[4]←1").empty());
  REQUIRE(!apl.env.start());
  CHECK(given_patches(apl.ws) == marks.patches);
  CHECK(apl.ws.changes.surface != generation);
  // Given back before START: nothing changed.
  generation = apl.ws.changes.surface;
  CHECK(apl("STATUS[3]←0").empty());
  CHECK(apl("STATUS[3]←1").empty());
  REQUIRE(!apl.env.start());
  CHECK(apl.ws.changes.surface == generation);
  // PATCHES of the user's own stay theirs when only the mark changes; other twists make them
  // again with IGDS's splines, as CHANGE TWISTS does.
  CHECK(apl("PATCHES[1;1;3;2;3]←PATCHES[1;1;3;2;3]×2").empty());
  REQUIRE(!apl.env.start());
  const Array own = apl.ws.patches;
  CHECK(apl("STATUS[4]←0").empty());
  REQUIRE(!apl.env.start());
  CHECK(apl.ws.patches == own);
  CHECK(!apl.ws.changes.derived);
  CHECK(apl("STATUS[3]←0").empty());
  REQUIRE(!apl.env.start());
  CHECK(given_patches(apl.ws) == interpolate(surface_input(apl.ws)).patches);
  CHECK(apl.ws.changes.derived);
}

TEST_CASE("PATCHES of the user's own stay theirs when only the grid changes afterwards") {
  Apl apl(surface(3, 3, 1, 1));
  CHECK(apl("PATCHES[1;1;3;2;3]←PATCHES[1;1;3;2;3]×2").empty());
  REQUIRE(!apl.env.start());
  const Array own = apl.ws.patches;
  REQUIRE(!apl.ws.changes.derived);
  // INTPN is made from them again; they are still not the inputs' interpolation, which the
  // session would make again in their place.
  CHECK(apl("INTCU←2").empty());
  REQUIRE(!apl.env.start());
  CHECK(apl.ws.patches == own);
  CHECK(!apl.ws.changes.derived);
  CHECK(apl("∧/,INTPN=FIT") == Lines{"1"});
}

TEST_CASE("START refuses a workspace that does not agree with itself, with the reason") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("NOCUR←4").empty());
  CHECK(apl.env.start() == "INPPN IS 6 BY 3, NOT 8 BY 3");
  CHECK(apl("NOCUR←3").empty());
  CHECK(!apl.env.start());
  // INTPN given other values: kept as given, and the session must keep them too; but its
  // nodes are the input points.
  CHECK(apl("INTPN[2;2;3]←5").empty());
  CHECK(!apl.env.start());
  CHECK(!apl.ws.changes.derived);
  CHECK(apl("INTPN[3;3;]=INPPN[4;]") == Lines{"1 1 1"});  // a node: curve 2, place 2
  CHECK(apl("INTPN[3;3;3]←INTPN[3;3;3]+1").empty());
  CHECK(apl.env.start() == "INTPN DOES NOT PASS THROUGH INPPN AT POINT 4");
  CHECK(apl("INTPN[3;3;3]←INTPN[3;3;3]-1").empty());
  CHECK(apl("INTPN←2 2 3⍴0").empty());
  CHECK(apl.env.start().value_or("").find("INTPN") != std::string::npos);
  // Emptied, PATCHES is made again from the inputs, and INTPN with it (the bad INTPN goes).
  CHECK(apl("PATCHES←⍳0").empty());
  REQUIRE(!apl.env.start());
  const Surface expected = interpolate({3, 2, 1, 1, &apl.ws.inppn, &apl.ws.inptg});
  CHECK(given_patches(apl.ws) == expected.patches);
  CHECK(apl.ws.intpn == expected.intpn);
  CHECK(apl.ws.changes.derived);
}

TEST_CASE("the manual's functions call igds's code") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("(1 2 3⍴1 2 3 4 5 6) ORTHOG 3") == Lines{"1 2", "4 5"});
  CHECK(apl("(1 1 3⍴1 2 3) ORTHOG 1") == Lines{"2 3"});
  CHECK(apl("(1 1 3⍴1 2 3) ORTHOG 4").at(0) == "DOMAIN ERROR");
  CHECK(apl("(1 1 2⍴1 2) ORTHOG 3").at(0) == "LENGTH ERROR");
  CHECK(apl("⍴INTPN ISOM 3 30") == Lines{"5 3 2"});
  CHECK(apl("⍴INTPN ASSON 110 130 120") == Lines{"5 3 2"});
  CHECK(apl("(INTPN ASSON 100 100 100)").at(0).starts_with("INCORRECT PARAMETER"));
  CHECK(apl("⍴INTPN CONIC 80 ¯60 40") == Lines{"5 3 2"});
  CHECK(apl("0 0 10 10 SCALE 2 1 2⍴0 0 4 2") == Lines{" 0 0", "", "10 5"});
  CHECK(apl("DESCR 1 3 3 30 0") == Lines{"IMAGE: SURFACE, ISOMETRIC, AXIS 3 ANGLE 30"});
  CHECK(apl("(3 4⍴'BUILCHANDISP') LUT 'DI'") == Lines{"3"});
  CHECK(apl("(3 4⍴'BUILCHANDISP') LUT 'X'") == Lines{"0"});
  CHECK(apl("COMDIS 'SURFACE ISOMETRIC 3 30'").empty());
  CHECK(apl.commands == std::vector<Lines>{{"DISPLAY", "SURFACE", "ISOMETRIC", "3", "30"}});
  CHECK(apl("COONS").empty());
  CHECK(apl("⍴PATCHES") == Lines{"2 1 3 4 4"});
  CHECK(apl("INIT").at(0).starts_with("INIT: "));
}

TEST_CASE("an image assigned is checked at START") {
  Workspace ws = make_interpolated(2, 2, 0, 0);
  Image image;
  image.desim = {1, Projection::isometric, {3, 30, 0}};
  image.points = Array({1, 2, 2});
  ws.image = std::make_shared<const Image>(image);
  Apl apl(std::move(ws));
  CHECK(apl("DESIM") == Lines{"1 3 3 30 0"});
  CHECK(apl("DESIM←1 9 0 0 0").empty());
  CHECK(apl.env.start().has_value());
  CHECK(apl("DESIM←1 4 1 0 0").empty());
  CHECK(!apl.env.start());
  CHECK(apl.ws.image->desim.projection == Projection::orthogonal);
  CHECK(apl.ws.image->drawn_from == 0);
  CHECK(apl("IMAGE←1 2 3⍴0").at(0) == "LENGTH ERROR");
}

TEST_CASE("a combs image in END APL: DESIM[1] is 3; IMAGE or DESIM assigned drop the combs") {
  Workspace ws = make_interpolated(3, 3, 1, 1);
  ws.image = std::make_shared<const Image>(image_of(ws, {3, Projection::orthogonal, {1, 0, 0}}));
  REQUIRE(!ws.image->combs.empty());
  Apl apl(std::move(ws));
  CHECK(apl("DESIM") == Lines{"3 4 1 0 0"});
  CHECK(apl("⍴IMAGE") == Lines{"5 5 2"});
  CHECK(apl("DESIM←3 4 2 0 0").empty());
  CHECK(!apl.env.start());
  CHECK(apl.ws.image->desim.what == 3);
  CHECK(apl.ws.image->combs.empty());
  CHECK(apl.ws.image->drawn_from == 0);
  CHECK(apl("DESIM←4 4 2 0 0").empty());
  CHECK(apl.env.start().has_value());  // refused: DESIM[1] IS NOT 0, 1, 2 OR 3
}

TEST_CASE("an IMAGE assigned in END APL is not said to have its projection's box") {
  Workspace ws = make_interpolated(3, 3, 1, 1);
  ws.image = std::make_shared<const Image>(image_of(ws, {1, Projection::orthogonal, {1, 0, 0}}));
  REQUIRE(ws.image->extent);
  Apl apl(std::move(ws));
  // The description alone: the points kept, and their box.
  CHECK(apl("DESIM←1 4 2 0 0").empty());
  CHECK(!apl.env.start());
  CHECK(apl.ws.image->extent);
  // The points: a box of its own, found when the image is drawn.
  CHECK(apl("IMAGE←IMAGE×2").empty());
  CHECK(!apl.env.start());
  CHECK_FALSE(apl.ws.image->extent);
}

TEST_CASE("workspace_variable and defined_variables") {
  Workspace ws = surface(2, 2, 0, 0);
  CHECK(workspace_variable(ws, "nocur")->ravel == Ravel{2});
  CHECK_FALSE(workspace_variable(ws, "IMAGE"));
  CHECK_FALSE(workspace_variable(ws, "FOO"));
  CHECK(defined_variables(ws) ==
        Lines{"INPPN", "INPTG", "INTCU", "INTPN", "INTST", "NOCUR", "NOSTR", "PATCHES", "STATUS"});
}

}  // namespace igds::test

namespace igds::test {

TEST_CASE("START after COONS: INTPN made again from the new PATCHES, never left stale") {
  Apl apl(surface(3, 3, 1, 1));
  CHECK(apl("INPPN[5;3]←7").empty());
  CHECK(apl("COONS").empty());
  REQUIRE(!apl.env.start());
  const Surface expected = interpolate({3, 3, 1, 1, &apl.ws.inppn, &apl.ws.inptg});
  CHECK(given_patches(apl.ws) == expected.patches);
  CHECK(apl.ws.intpn == expected.intpn);
  CHECK(apl("INTPN[3;3;3]") == Lines{"7"});
  // PATCHES of its own: INTPN is made from them, and they must hold the input points.
  CHECK(apl("PATCHES[1;1;3;2;3]←PATCHES[1;1;3;2;3]×2").empty());  // a tangent, not a corner
  REQUIRE(!apl.env.start());
  CHECK(!apl.ws.changes.derived);
  CHECK(apl("∧/,INTPN=FIT") == Lines{"1"});
  CHECK(apl("PATCHES[1;1;1;1;1]←99").empty());
  CHECK(apl.env.start() == "PATCHES DOES NOT PASS THROUGH INPPN AT POINT 1");
}

TEST_CASE("no infinity or NaN enters the workspace") {
  Apl apl(surface(3, 2, 1, 1));
  const Workspace before = apl.ws;
  auto big = apl::Value::of_numbers({6, 3}, std::vector<double>(18, 1.0));
  big.mutable_numbers()[4] = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(apl.env.check("INPPN", big), apl::Error);
  big.mutable_numbers()[4] = std::nan("");
  CHECK_THROWS_AS(apl.env.check("INPPN", big), apl::Error);
  CHECK(apl("INPPN[1;1]←1E308×10").at(0) == "DOMAIN ERROR");
  CHECK(apl.ws == before);
}

TEST_CASE("the blending functions, DISTA and the spline of one line are igds's kernels") {
  Apl apl(surface(3, 2, 1, 1));
  const double s = 0.3;
  const Hermite h = hermite(s);
  CHECK(apl("F0 0 0.3 1") == Lines{fmt::format("1 {} 0", apl::format_number(h.f0, 10))});
  CHECK(apl("(F1 0.3),(G0 0.3),G1 0.3") ==
        Lines{fmt::format("{} {} {}", apl::format_number(h.f1, 10), apl::format_number(h.g0, 10),
                          apl::format_number(h.g1, 10))});
  CHECK(apl("DISTA 3 3⍴0 0 0 3 4 0 3 4 12") == Lines{"5 12"});
  CHECK(apl("PUNTI←4 3⍴0 0 0 1 2 0 3 3 1 4 3 3").empty());
  CHECK(apl("TANGENTI←2 3⍴1 0 0 0 0 1").empty());
  CHECK(apl("⍴CURVILINEO") == Lines{"4 7"});
  // The system of COEFFICIENTI and NOTO solved by APL gives CURVILINEO's tangents.
  CHECK(apl("T←CURVILINEO[;5 6 7]").empty());
  CHECK(apl("S←(3,⍴T[;1])⍴0").empty());
  CHECK(apl("S[1;]←(NOTO 1)⌹COEFFICIENTI").empty());
  CHECK(apl("S[2;]←(NOTO 2)⌹COEFFICIENTI").empty());
  CHECK(apl("S[3;]←(NOTO 3)⌹COEFFICIENTI").empty());
  CHECK(apl("∧/,1E¯9>|T-⍉S") == Lines{"1"});
  CHECK(apl("CURVILINEO[1;1]=DISTA PUNTI[1 2;]") == Lines{"1"});
  CHECK(apl("NOTO 4").at(0) == "DOMAIN ERROR");
  CHECK(apl("TANGENTI←1 3⍴0").empty());
  CHECK(apl("CURVILINEO").at(0) == "LENGTH ERROR");
}

TEST_CASE("ASSON is PROSPAR of the points scaled, as the manual says") {
  Apl apl(surface(3, 2, 1, 1));
  // kx ky kz of the angles 110 130 120 (docs/kernels.md), then PROSPAR with (γ-90) (β-90).
  CHECK(apl("R←○(110 130 120)÷180").empty());
  CHECK(apl("K←(-2○R[2 3 1])÷(1○R[1 2 3])×1○R[3 1 2]").empty());
  CHECK(apl("P←1 4 3⍴0 0 0 1 2 3 ¯4 5 6 7 ¯8 9").empty());
  CHECK(apl("Q←(P×1 4 3⍴K*0.5) PROSPAR 30 40").empty());
  CHECK(apl("∧/,1E¯12>|Q-P ASSON 110 130 120") == Lines{"1"});
  CHECK(apl("(1 1 3⍴1 2 3) PROSPAR 0 0") == Lines{"1 3"});  // X = y - x, Y = z
  CHECK(apl("(1 1 3⍴1 2 3) PROSPAR 1 2 3").at(0) == "LENGTH ERROR");
}

TEST_CASE("the COMxxx functions take GETCOM's codes as well as words") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("COMCHA 1").empty());
  CHECK(apl.commands.back() == Lines{"CHANGE", "GRID"});
  CHECK(apl("COMDIS 5 3 3 30").empty());
  CHECK(apl.commands.back() == Lines{"DISPLAY", "SURFACE", "ISOMETRIC", "3", "30"});
  CHECK(apl("COMDIS 4 4 3").empty());
  CHECK(apl.commands.back() == Lines{"DISPLAY", "INPUT", "ORTHOGONAL", "YZ"});
  CHECK(apl("COMSAV APLNAME 'HULL'").empty());
  CHECK(apl.commands.back() == Lines{"SAVE", "HULL"});
  CHECK(apl("COMSTO 3,APLNAME 'PIC IGDSIMAG'").empty());
  CHECK(apl.commands.back() == Lines{"STORE", "FILE", "PIC"});
  CHECK(apl("COMCHA 'TW MARKS'").empty());
  CHECK(apl.commands.back() == Lines{"CHANGE", "TW", "MARKS"});
  CHECK(apl("COMCHA 9").at(0) == "DOMAIN ERROR");
  CHECK(apl("COMDIS 5 9").at(0) == "DOMAIN ERROR");
  // PARxx: the codes of the words after a command; GETCOM: a command typed, as codes.
  CHECK(apl("PARDI 'SURFACE ASSON 110 130 120'") == Lines{"5 2 110 130 120"});
  CHECK(apl("PARCH 'TW MARKS'") == Lines{"4 2"});
  CHECK(apl("PARSA 'HULL'") == Lines{apl("APLNAME 'HULL'").at(0)});
  CHECK(apl("PARCH 'SIDEWAYS'").at(0) == "INCORRECT CHOICE OF PARAMETERS");
  apl.input = {"DISPLAY SURFACE CONIC 10 20 30"};
  CHECK(apl("GETCOM") == Lines{"4 5 1 10 20 30"});
  apl.input = {"FROBNICATE"};
  CHECK(apl("GETCOM") == Lines{"INCORRECT COMMAND OR PARAMETERS", "0"});
  apl.input = {"CHANGE", "GRID"};  // the option asked as CHANGE asks it
  CHECK(apl("C←GETCOM") == Lines{"GRID, TANGENTS, POINTS OR TWISTS?"});
  CHECK(apl("C") == Lines{"2 1"});
  apl.input = {"POINTS"};  // PARCH asks the option as CHANGE does
  CHECK(apl("PARCH ''") == Lines{"GRID, TANGENTS, POINTS OR TWISTS?", "3"});
  CHECK(apl("COMCHA 1↓C").empty());
  CHECK(apl.commands.back() == Lines{"CHANGE", "GRID"});
}

TEST_CASE("ALFINP, NUMINP, EXPL: lines read, HELP answered there") {
  Apl apl(surface(3, 2, 1, 1));
  apl.input = {"HELP SHORT", "HELLO"};
  CHECK(apl("ALFINP 2") ==
        Lines{"CHANGE: " + std::string(find_command("CHANGE")->summary), "HELLO"});
  CHECK(apl.ws.status[0] == 0);
  apl.input = {"1 ¯2 3.5 -4", "X", "5"};
  CHECK(apl("NUMINP 0") == Lines{"1 ¯2 3.5 ¯4"});
  CHECK(apl("NUMINP 0") == Lines{"INCORRECT ENTRY", "5"});
  CHECK(apl("EXPLONG 1").at(0).starts_with("BUILD"));
  CHECK(apl("EXPL 99").at(0) == "DOMAIN ERROR");
  CHECK(apl("ALFINP 0").at(0) == "INTERRUPT");  // the end of the input
}

TEST_CASE("the session functions: AUTOMSAVE, RESTORE, DEFVAR, INIT") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("AUTOMSAVE").empty());
  CHECK(apl.session_saves == 1);
  CHECK(apl("NOCUR←4").empty());
  CHECK(apl("AUTOMSAVE").at(0) == "CANNOT START: INPPN IS 6 BY 3, NOT 8 BY 3");
  CHECK(apl.session_saves == 1);
  CHECK(apl("RESTORE").at(0) == "THE SESSION ON THE DISK CANNOT BE READ");
  CHECK(apl("V←1 2").empty());
  const auto mine = apl.ws.apl_variables;
  apl.saved_session = surface(2, 2, 0, 0);
  apl.saved_session->apl_variables = {{"OLD", {}, false, {1}, {}}};
  CHECK(apl("RESTORE").empty());
  CHECK(apl("NOCUR,⍴INTPN") == Lines{"2 2 2 3"});
  CHECK(!apl.env.start());              // nothing pending: NOCUR←4 went with the restored surface
  CHECK(apl.ws.apl_variables == mine);  // the APL workspace's own stay
  CHECK(apl("DEFVAR").empty());
  CHECK(apl("NOCUR,⍴INPPN") == Lines{"0 0"});
  CHECK(apl.ws.apl_variables == mine);
  Workspace empty;
  empty.apl_variables = mine;
  CHECK(apl.ws == empty);
}

TEST_CASE("the devices: PLOTG PLOTP PLOTV, TKX and TEKG TEKP TEKV TEKC, DISPLA, OUT") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("PLOTG 4 2⍴0 0 1 1 2 0 3 3").empty());
  REQUIRE(apl.plotted.size() == 1);
  CHECK(apl.plotted[0].drawing.size() == 2);  // two segments
  CHECK(apl("PLOTV 3 2⍴0 0 1 1 2 0").empty());
  CHECK(apl.plotted.back().drawing.size() == 1);
  CHECK(apl("PLOTP 3 2⍴0 0 1 1 2 0").empty());
  CHECK(apl.plotted.back().drawing.size() == 3);
  CHECK(apl("PLOTG 3⍴0").at(0) == "LENGTH ERROR");
  CHECK(apl("⍴TKX 2 2⍴10 20 1023 779") == Lines{"8"});
  CHECK(apl("TKX 1 2⍴1024 0").at(0) == "DOMAIN ERROR");
  CHECK(apl("TEKG TKX 2 2⍴10 20 1023 779") == Lines{"IMAGE: TEKG"});
  REQUIRE(apl.drawn.size() == 1);
  // The screen's corners, then the segment, in the 4013's addresses.
  const Drawing2& d = apl.drawn[0].drawing;
  REQUIRE(d.size() == 3);
  const auto seg = d.points(d.items()[2]);
  CHECK(Point2(seg[0]) == Point2{10, 20});
  CHECK(Point2(seg[1]) == Point2{1023, 779});
  CHECK(apl("TEKV 'ABCD'").at(0) == "DOMAIN ERROR");
  CHECK(apl("TEKP 'ABC'").at(0) == "LENGTH ERROR");
  CHECK(apl("'HELLO' TEKC 100 200") == Lines{"IMAGE: TEKC"});
  CHECK(apl("OUT 'A LINE'") == Lines{"A LINE"});
  CHECK(apl("DISPLA").at(0) == "IMAGE NOT FOUND");
  CHECK(apl("COMDIS 'SURFACE ISOMETRIC 3 30'").empty());
  apl.ws.image = std::make_shared<const Image>(Image{});
  CHECK(apl("DISPLA").empty());
  CHECK(apl.shown == 1);
  CHECK(apl("PLOTHP").empty());
  CHECK(apl.commands.back() == Lines{"PLOT", "SELECTRIC"});
}

TEST_CASE(")HELP is the APL environment's HELP; HELP and * lines are APL's") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl(")HELP SHORT").at(0).starts_with("Type an APL statement"));
  CHECK(apl.ws.status[0] == 0);
  CHECK(apl(")HELP LONG").at(0).starts_with("The APL environment is APL\\360"));
  CHECK(apl.ws.status[0] == 1);
  CHECK(apl("STATUS[1]") == Lines{"1"});
  CHECK(apl(")HELP MAYBE") == Lines{"INCORRECT COMMAND"});
  CHECK(apl("H←5").empty());
  CHECK(apl("H") == Lines{"5"});
  CHECK(apl("HELP").at(0) == "VALUE ERROR");
  CHECK(apl("*1") == Lines{"2.718281828"});
}

TEST_CASE(")LOAD: no stale copy of a variable afterwards") {
  TempDir dir;
  const Disk disk(dir.path());
  Apl apl(surface(3, 2, 1, 1), &disk);
  CHECK(apl("INPPN[1;1]").at(0) == "0");
  CHECK(apl("INPPN[1;1]←5").empty());
  apl.run = [&apl](const Lines& words) {  // RESTORE replaces the surface
    if (words[0] != "RESTORE") return;
    apl.ws = surface(2, 2, 0, 0);
    apl.ws.inppn.ravel[0] = 9;
  };
  CHECK(apl(")LOAD HULL") == Lines{"LOADED HULL"});
  CHECK(apl("INPPN[1;1]") == Lines{"9"});
  CHECK(!apl.env.start());  // INPPN←5 went with the surface it was made on
  CHECK(apl.ws.inppn.ravel[0] == 9);
}

TEST_CASE("the user's variables and functions are the workspace's: kept, back in a new session") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("V←2 3⍴⍳6").empty());
  CHECK(apl("C←'⍴AB'").empty());
  CHECK(apl("∇Z←F X").empty());
  CHECK(apl("Z←X×V∇").empty());
  CHECK(apl.ws.functions == std::vector<Lines>{{"Z←F X", "Z←X×V"}});
  REQUIRE(apl.ws.apl_variables.size() == 2);
  CHECK(apl.ws.apl_variables[0] == AplVariable{"C", {3}, true, {}, U"⍴AB"});
  CHECK(apl.ws.apl_variables[1] == AplVariable{"V", {2, 3}, false, {1, 2, 3, 4, 5, 6}, {}});
  // The system variables are the session's, not the user's.
  CHECK(apl("⎕IO←0").empty());
  CHECK(apl("⎕PP←5").empty());
  CHECK(apl.ws.apl_variables.size() == 2);
  CHECK(apl("⎕IO←1").empty());
  // Changed in place, erased: the workspace follows.
  CHECK(apl("V[1;1]←¯0.5").empty());
  CHECK(apl.ws.apl_variables[1].numbers[0] == -0.5);
  CHECK(apl(")ERASE C").empty());
  CHECK(apl.ws.apl_variables.size() == 1);
  CHECK(apl("C←'⍴AB'").empty());

  // A new environment on that workspace (a new start of igds) has them.
  Apl again(apl.ws);
  CHECK(again.reported.empty());
  CHECK(again("F 2") == Lines{"¯1  4  6", " 8 10 12"});
  CHECK(again("C") == Lines{"⍴AB"});
  CHECK(again.ws.apl_variables == apl.ws.apl_variables);

  // One whose name is a function's now is said and left out; the others come.
  Workspace ws = apl.ws;
  ws.apl_variables.push_back({"FIT", {}, false, {1}, {}});
  Apl clash(ws);
  CHECK(clash.reported == Lines{"SYNTAX ERROR: FIT"});
  CHECK(clash("C") == Lines{"⍴AB"});
  CHECK(clash.ws.apl_variables == apl.ws.apl_variables);

  // Functions forged in a session or a file are defined as typed ones are, or said and left out.
  Workspace forged = apl.ws;
  forged.functions = {{"Z←G\xFF X", "Z←X"}, {"Z←INPPN X", "Z←X"}, {"Z←H X", "Z←X+\xE2\x88"}};
  forged.apl_variables = {{"\xE2\x88\x86X", {}, false, {3}, {}}};
  Apl odd(forged);
  CHECK(odd.reported.size() == 2);
  CHECK(odd("∆X") == Lines{"3"});
  CHECK(odd.ws.functions.size() == 1);

  // The session file holds at most 8 MB of them: a larger one is said once, and )SAVE keeps it.
  CHECK(apl("B←1100000⍴1.5") ==
        Lines{"B IS NOT KEPT WITH THE SESSION (MORE THAN 8 MB IN ALL); )SAVE KEEPS IT"});
  CHECK(apl("B←B+1").empty());
  CHECK(apl.ws.apl_variables.size() == 2);
}

TEST_CASE(")SAVE, )LOAD, )COPY and )CLEAR act on the whole APL workspace") {
  TempDir dir;
  const Disk disk(dir.path());
  Apl apl(surface(3, 2, 1, 1), &disk);
  const Workspace saved_surface = apl.ws;
  apl.run = [&](const Lines& words) {  // RESTORE gives back the surface SAVE saved
    if (words[0] == "RESTORE") {
      apl.ws.inppn = saved_surface.inppn;
      apl.ws.patches = saved_surface.patches;
      apl.ws.intpn = saved_surface.intpn;
    }
  };
  CHECK(apl("V←1 2 3").empty());
  CHECK(apl("T←2 2⍴'ABCD'").empty());
  CHECK(apl("∇Z←F X").empty());
  CHECK(apl("Z←X+V∇").empty());
  CHECK(apl(")SAVE W1") == Lines{"SAVED W1"});
  CHECK(apl.commands.back() == Lines{"SAVE", "W1"});
  const auto kept = apl.ws.apl_variables;
  const auto functions = apl.ws.functions;

  // )CLEAR: no variables, no functions; the surface is IGDS's and stays.
  CHECK(apl(")CLEAR") == Lines{"CLEAR WS"});
  CHECK(apl("V").at(0) == "VALUE ERROR");
  CHECK(apl.ws.apl_variables.empty());
  CHECK(apl.ws.functions.empty());
  CHECK(apl.ws.inppn == saved_surface.inppn);

  // )LOAD: the saved functions and variables replace the session's, the surface is restored, and
  // nothing assigned before is written back by START.
  CHECK(apl("V←9").empty());
  CHECK(apl("U←9").empty());
  CHECK(apl("INPPN[1;1]←5").empty());
  CHECK(apl(")LOAD W1") == Lines{"LOADED W1"});
  CHECK(apl.commands.back() == Lines{"RESTORE", "W1"});
  CHECK(apl("F 1") == Lines{"2 3 4"});
  CHECK(apl("T") == Lines{"AB", "CD"});
  CHECK(apl("U").at(0) == "VALUE ERROR");
  CHECK(apl.ws.apl_variables == kept);
  CHECK(apl.ws.functions == functions);
  CHECK(!apl.env.start());
  CHECK(apl.ws.inppn == saved_surface.inppn);

  // )COPY: those named, or all, over the session's of the same names; the surface untouched.
  const std::size_t commands = apl.commands.size();
  CHECK(apl("V←7").empty());
  CHECK(apl("T←'X'").empty());
  CHECK(apl(")COPY W1 V NOPE") == Lines{"NOT FOUND: NOPE", "COPIED W1"});
  CHECK(apl("V") == Lines{"1 2 3"});
  CHECK(apl("T") == Lines{"X"});
  CHECK(apl(")ERASE F").empty());
  CHECK(apl("F←5").empty());  // a variable gives way to a function copied
  CHECK(apl(")COPY W1") == Lines{"COPIED W1"});
  CHECK(apl("F 0") == Lines{"1 2 3"});
  CHECK(apl("T") == Lines{"AB", "CD"});
  CHECK(apl.commands.size() == commands);

  // Files that are not there or do not read change nothing.
  CHECK(apl(")COPY NONE") == Lines{"FILE NOT FOUND"});
  CHECK(apl(")LOAD ../W1") == Lines{"INCORRECT PARAMETER"});
  std::string bytes = read_file(disk.path("W1", "IGDSAPLW"));
  bytes[bytes.size() - 12] ^= 4;
  rewrite_file(disk.path("W1", "IGDSAPLW"), bytes);
  CHECK(apl("V←0").empty());
  CHECK(apl(")LOAD W1") == Lines{"FILE DAMAGED: W1.IGDSAPLW (CHECKSUM); NOTHING LOADED"});
  CHECK(apl(")COPY W1") == Lines{"FILE DAMAGED: W1.IGDSAPLW (CHECKSUM); NOTHING COPIED"});
  CHECK(apl("V") == Lines{"0"});
  CHECK(apl.commands.size() == commands);

  // A workspace saved without a surface leaves the current one at )LOAD (a W2.IGDSDATA there is
  // of another time); a NAME.IGDSDATA alone (SAVE of IGDS) is the surface alone.
  Apl empty(Workspace{}, &disk);
  CHECK(empty("X←1").empty());
  CHECK(empty(")SAVE W2") == Lines{"SAVED W2"});
  CHECK(empty.commands.empty());
  CHECK(apl(")LOAD W2") == Lines{"LOADED W2"});
  CHECK(apl.commands.size() == commands);
  CHECK(apl("X") == Lines{"1"});
  CHECK(apl("V").at(0) == "VALUE ERROR");
  CHECK(apl(")LOAD W3") == Lines{"LOADED W3"});
  CHECK(apl.commands.back() == Lines{"RESTORE", "W3"});
  CHECK(apl("X") == Lines{"1"});
}

}  // namespace igds::test

namespace igds::test {

TEST_CASE("STATE and WRT on the disk") {
  TempDir dir;
  const Disk disk(dir.path());
  Apl apl(surface(3, 2, 1, 1), &disk);
  CHECK(apl("STATE 'CARDS TEXT'") == Lines{"0"});
  // A new file of integers, 3 to a record of width 5; then two records of F8.2 added.
  CHECK(apl("(1 1 5 0 3,APLNAME 'CARDS TEXT') WRT 2 2⍴1 22 ¯333 4444").empty());
  CHECK(apl("STATE 'CARDS TEXT'") == Lines{"1"});
  CHECK(apl("(0 3 8 2 1,APLNAME 'CARDS TEXT') WRT 1.5 ¯2.25").empty());
  CHECK(apl("(0 2 1 0 1,APLNAME 'CARDS TEXT') WRT 2 3⍴'AB CD '").empty());
  CHECK(read_file(disk.path("CARDS", "TEXT")) ==
        "    1   22 -333\n 4444\n    1.50\n   -2.25\nAB\nCD\n");
  CHECK(apl("(1 1 2 0 1,APLNAME 'CARDS TEXT') WRT 123").empty());
  CHECK(read_file(disk.path("CARDS", "TEXT")) == "**\n");
  // igds's own files are not for WRT; bad controls are DOMAIN ERROR.
  CHECK(apl("(1 1 5 0 3,APLNAME 'BINSAVE IGDSCONT') WRT 1").at(0) == "DOMAIN ERROR");
  CHECK(apl("(1 5 5 0 3,APLNAME 'CARDS TEXT') WRT 1").at(0) == "DOMAIN ERROR");
  CHECK(apl("(1 1 5 0 30,APLNAME 'CARDS TEXT') WRT 1").at(0) == "DOMAIN ERROR");
  CHECK(apl("STATE 'A/B TEXT'").at(0) == "DOMAIN ERROR");
}

}  // namespace igds::test
