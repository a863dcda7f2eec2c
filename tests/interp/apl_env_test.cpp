// END APL: the workspace variables displayed as APL does.
#include "interp/apl_env.h"

#include <doctest/doctest.h>

namespace igds::test {

using Lines = std::vector<std::string>;

namespace {

Array array(std::vector<std::size_t> shape, std::vector<double> ravel) {
  Array a;
  a.shape = std::move(shape);
  a.ravel = std::move(ravel);
  return a;
}

Workspace small_workspace() {
  Workspace ws;
  ws.nocur = 2;
  ws.nostr = 2;
  ws.intcu = 1;
  ws.inppn = array({4, 3}, {0, 0, 0, 0, 10, 0, 10, 0, 0, 10, 10, -5.5});
  return ws;
}

}  // namespace

TEST_CASE("scalars, vectors and empty arrays") {
  Array scalar;
  scalar.ravel = {-3};
  CHECK(apl_display(scalar) == Lines{"¯3"});
  CHECK(apl_shape(scalar) == "");
  CHECK(apl_display(array({3}, {1, -2.5, 1e-7})) == Lines{"1 ¯2.5 1E¯7"});
  CHECK(apl_shape(array({3}, {1, 2, 3})) == "3");
  CHECK(apl_display(Array()) == Lines{""});
  CHECK(apl_shape(Array()) == "0");
  CHECK(apl_display(array({0, 4}, {})) == Lines{""});
}

TEST_CASE("a matrix: columns aligned on their decimal points") {
  CHECK(apl_display(array({2, 3}, {1.5, 10, -2, 100, 0.25, 3})) ==
        Lines{"  1.5 10    ¯2", "100    0.25  3"});
  CHECK(apl_display(array({2, 2}, {1, 2, 3, 4})) == Lines{"1 2", "3 4"});
}

TEST_CASE("planes separated by blank lines, one more per outer axis") {
  CHECK(apl_display(array({2, 1, 2}, {1, 2, 3, 4})) == Lines{"1 2", "", "3 4"});
  Lines four = apl_display(array({2, 2, 1, 1}, {1, 2, 3, 4}));
  CHECK(four == Lines{"1", "", "2", "", "", "3", "", "4"});
  CHECK(apl_shape(array({2, 2, 1, 1}, {1, 2, 3, 4})) == "2 2 1 1");
}

TEST_CASE("the workspace variables by name") {
  Workspace ws = small_workspace();
  CHECK(apl_display(*workspace_variable(ws, "nocur")) == Lines{"2"});
  CHECK(apl_display(*workspace_variable(ws, "INPPN")) ==
        Lines{" 0  0  0", " 0 10  0", "10  0  0", "10 10 ¯5.5"});
  CHECK(apl_display(*workspace_variable(ws, "STATUS")) == Lines{"1 0 0 0 0 0 0 0 0 0"});
  CHECK_FALSE(workspace_variable(ws, "IMAGE"));
  CHECK_FALSE(workspace_variable(ws, "DEST1"));
  CHECK_FALSE(workspace_variable(ws, "FOO"));
  CHECK(defined_variables(ws) ==
        Lines{"INPPN", "INPTG", "INTCU", "INTPN", "INTST", "NOCUR", "NOSTR", "PATCHES", "STATUS"});

  Image image;
  image.desim = {1, Projection::isometric, {3, 30, 0}};
  image.points = array({1, 2, 2}, {0, 1, 2, 3});
  ws.image = std::make_shared<const Image>(image);
  ws.temp2 = ws.image;
  CHECK(apl_display(*workspace_variable(ws, "DESIM")) == Lines{"1 3 3 30 0"});
  CHECK(apl_display(*workspace_variable(ws, "IMAGE")) == Lines{"0 1", "2 3"});
  CHECK(apl_display(*workspace_variable(ws, "DEST2")) == Lines{"1 3 3 30 0"});
  CHECK(apl_shape(*workspace_variable(ws, "TEMP2")) == "1 2 2");
  CHECK(defined_variables(ws).size() == 13);
}

TEST_CASE("lines typed in the APL environment") {
  const Workspace ws = small_workspace();
  CHECK(apl_line(ws, "NOSTR").lines == Lines{"2"});
  CHECK(apl_line(ws, "⍴INPPN").lines == Lines{"4 3"});
  CHECK(apl_line(ws, "⍴ inppn").lines == Lines{"4 3"});
  CHECK(apl_line(ws, "RHO INPPN").lines == Lines{"4 3"});
  CHECK(apl_line(ws, "⍴NOCUR").lines == Lines{""});
  CHECK(apl_line(ws, ")VARS").lines ==
        Lines{"INPPN INPTG INTCU INTPN INTST NOCUR NOSTR PATCHES STATUS"});
  CHECK(apl_line(ws, "IMAGE").lines == Lines{"VALUE ERROR"});
  CHECK(apl_line(ws, "XYZ").lines == Lines{"VALUE ERROR"});
  CHECK(apl_line(ws, "⍴XYZ").lines == Lines{"VALUE ERROR"});
  CHECK(apl_line(ws, "2+2").lines == Lines{"SYNTAX ERROR"});
  CHECK(apl_line(ws, "NOCUR NOSTR").lines == Lines{"SYNTAX ERROR"});
  CHECK(apl_line(ws, ")LOAD 5 IGDS").lines == Lines{"SYNTAX ERROR"});
  CHECK(apl_line(ws, "").lines.empty());
  CHECK(apl_line(ws, "START").next == AplNext::start);
  CHECK(apl_line(ws, ")off").next == AplNext::off);
  CHECK(apl_line(ws, ")OFF CMS").next == AplNext::off);
  CHECK(apl_line(ws, "NOCUR").next == AplNext::stay);
}

}  // namespace igds::test
