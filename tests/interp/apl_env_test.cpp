// END APL: an APL\360 session on the workspace (interp/apl_env.h): the IGDS globals read and
// assigned, checked at once for their kind and at START against each other, PATCHES and INTPN
// made again from changed inputs, and the manual's functions calling igds's own code.
#include "interp/apl_env.h"

#include <doctest/doctest.h>

#include "tests/workspace/disk_fixtures.h"
#include "workspace/kernels/surface.h"

namespace igds::test {

using Lines = std::vector<std::string>;

namespace {

// An environment on `ws` that keeps what it says, reports and runs.
struct Apl {
  Workspace ws;
  Lines said, reported;
  std::vector<Lines> commands;
  AplEnvironment env;
  explicit Apl(Workspace w) : ws(std::move(w)), env(ws, hooks()) {}
  AplEnvironment::Hooks hooks() {
    AplEnvironment::Hooks h;
    h.say = [this](std::string_view l) { said.emplace_back(l); };
    h.report = [this](std::string_view l) { reported.emplace_back(l); };
    h.read = [](std::string_view) { return std::nullopt; };
    h.command = [this](const Lines& words) { commands.push_back(words); };
    h.save = [](std::string_view name) { return "SAVE " + std::string(name); };
    h.load = [](std::string_view name) { return "RESTORE " + std::string(name); };
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
  CHECK(apl(")VARS") == Lines{"INPPN INPTG INTCU INTPN INTST NOCUR NOSTR PATCHES STATUS X"});
  std::string fns;
  for (const auto& line : apl(")FNS")) fns += line + " ";
  CHECK(fns ==
        "ASSON COMBUI COMCHA COMDIS COMEND COMPLO COMRES COMSAV COMSTO COMWRI CONIC COONS DESCR "
        "FIT INIT ISOM LUT ORTHOG SCALE START ");
}

TEST_CASE("an assignment of the wrong kind is refused at once and changes nothing") {
  Apl apl(surface(3, 2, 1, 1));
  const Workspace before = apl.ws;
  CHECK(apl("NOCUR←'A'").at(0) == "DOMAIN ERROR");
  CHECK(apl("NOCUR←1 2").at(0) == "LENGTH ERROR");
  CHECK(apl("NOCUR←2.5").at(0) == "DOMAIN ERROR");
  CHECK(apl("INPPN←5").at(0) == "RANK ERROR");
  CHECK(apl("STATUS←1 2 3").at(0) == "LENGTH ERROR");
  CHECK(apl("DESIM←1 3 3 30 0").at(0) == "VALUE ERROR");  // no image to describe
  // The first assignment of a failing statement is not made either.
  CHECK(apl("INTCU←4 ◊ NOCUR←'A'").empty() == false);
  CHECK(apl("Y←(INTCU←4)+'A'").at(0) == "DOMAIN ERROR");
  CHECK(apl.ws == before);
  CHECK(!apl.env.start());
}

TEST_CASE("START makes PATCHES and INTPN again from changed inputs") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("INPPN[5;3]←2.5").empty());
  CHECK(apl.ws.inppn.ravel[3 * 4 + 2] == 2.5);
  CHECK(apl("INTCU←2").empty());
  REQUIRE(!apl.env.start());
  const Surface expected = interpolate({3, 2, 2, 1, &apl.ws.inppn, &apl.ws.inptg});
  CHECK(apl.ws.patches == expected.patches);
  CHECK(apl.ws.intpn == expected.intpn);
  CHECK(apl.ws.changes.derived);
  CHECK(apl("⍴INTPN") == Lines{"7 3 3"});
  // FIT is the grid of the current PATCHES, as igds computes it.
  CHECK(apl("∧/,FIT=INTPN") == Lines{"1"});
}

TEST_CASE("START refuses a workspace that does not agree with itself, with the reason") {
  Apl apl(surface(3, 2, 1, 1));
  CHECK(apl("NOCUR←4").empty());
  CHECK(apl.env.start() == "INPPN IS 6 BY 3, NOT 8 BY 3");
  CHECK(apl("NOCUR←3").empty());
  CHECK(!apl.env.start());
  // INTPN given other values: kept as given, and the session must keep them too.
  CHECK(apl("INTPN←INTPN×2").empty());
  CHECK(!apl.env.start());
  CHECK(!apl.ws.changes.derived);
  CHECK(apl("INTPN←2 2 3⍴0").empty());
  CHECK(apl.env.start().value_or("").find("INTPN") != std::string::npos);
  // Emptied, PATCHES is made again from the inputs, and INTPN with it (the bad INTPN goes).
  CHECK(apl("PATCHES←⍳0").empty());
  REQUIRE(!apl.env.start());
  const Surface expected = interpolate({3, 2, 1, 1, &apl.ws.inppn, &apl.ws.inptg});
  CHECK(apl.ws.patches == expected.patches);
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
  CHECK(apl(")SAVE HULL") == Lines{"SAVE HULL"});
  CHECK(apl(")LOAD HULL") == Lines{"RESTORE HULL"});
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

TEST_CASE("workspace_variable and defined_variables") {
  Workspace ws = surface(2, 2, 0, 0);
  CHECK(workspace_variable(ws, "nocur")->ravel == std::vector<double>{2});
  CHECK_FALSE(workspace_variable(ws, "IMAGE"));
  CHECK_FALSE(workspace_variable(ws, "FOO"));
  CHECK(defined_variables(ws) ==
        Lines{"INPPN", "INPTG", "INTCU", "INTPN", "INTST", "NOCUR", "NOSTR", "PATCHES", "STATUS"});
}

}  // namespace igds::test
