// The words TAB completion offers at READY.
#include <doctest/doctest.h>

#include <algorithm>

#include "commands/picture.h"
#include "interp/interpreter.h"
#include "tests/support/process.h"
#include "tests/support/scripted.h"

namespace igds::test {

namespace {

bool has(const std::vector<std::string>& words, std::string_view w) {
  return std::find(words.begin(), words.end(), w) != words.end();
}

}  // namespace

TEST_CASE("completion: commands, then their options, then projections") {
  TempDir dir;
  Disk disk(dir.path());
  Session session(disk);
  StringOutput out;
  Terminal terminal(TermMode::none, {}, out);
  Interpreter interpreter(Options{}, disk, session, session.load(), terminal);

  auto commands = interpreter.completions({});
  CHECK(commands.size() == command_table().size());
  CHECK(commands.front() == "BUILD");
  CHECK(has(commands, "EXPORT"));

  CHECK(interpreter.completions({"d"}) == std::vector<std::string>{"FIRST", "SECOND", "FILE",
                                                                   "INPUT", "SURFACE", "PICTURE",
                                                                   "HIDDEN", "COMBS"});
  CHECK(interpreter.completions({"E"}) == std::vector<std::string>{"APL", "CMS"});
  CHECK(interpreter.completions({"BUILD"}).empty());
  CHECK(interpreter.completions({"NOSUCH"}).empty());

  auto projections = interpreter.completions({"D", "SU"});
  CHECK(has(projections, "ASSONOMETRIC"));
  CHECK(has(projections, "AXONOMETRIC"));
  CHECK(has(projections, "XZ"));
}

TEST_CASE("describe_line: what the none mode prints for a DISPLAY") {
  CHECK(describe_line({0, Projection::orthogonal, {3, 0, 0}}) == "IMAGE: INPUT, ORTHOGONAL YZ");
  CHECK(describe_line({1, Projection::conic, {100, -50, 80}}) ==
        "IMAGE: SURFACE, CONIC, VIEW POINT 100 ¯50 80");
  CHECK(describe_line({1, Projection::isometric, {3, 30, 0}}) ==
        "IMAGE: SURFACE, ISOMETRIC, AXIS 3 ANGLE 30");
  CHECK(describe_line({0, Projection::assonometric, {110, 130, 120}}) ==
        "IMAGE: INPUT, ASSONOMETRIC 110 130 120");
}

}  // namespace igds::test
