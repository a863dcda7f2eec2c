// The session: reports with a caret, statements that fail change nothing, the host's names
// and functions, ⎕ and ⍞, system commands, START and )OFF, and the limits.
#include "interp/apl/apl_session.h"

#include <doctest/doctest.h>

#include <signal.h>
#include <unistd.h>

#include <stdexcept>

#include "apl_support.h"
#include "workspace/kernels/interrupt.h"

namespace igds::apl::test {

TEST_CASE("a report: the error, the statement, a caret under the point of failure") {
  CHECK(apl("1 2+1 2 3") == Lines{"LENGTH ERROR", "      1 2+1 2 3", "         ^"});
  CHECK(apl("X+1") == Lines{"VALUE ERROR", "      X+1", "      ^"});
  CHECK(apl("2×÷0") == Lines{"DOMAIN ERROR", "      2×÷0", "        ^"});
  CHECK(apl("(2 2⍴1)[3;1]") == Lines{"INDEX ERROR", "      (2 2⍴1)[3;1]", "             ^"});
  CHECK(apl("2+") == Lines{"SYNTAX ERROR", "      2+", "       ^"});
  CHECK(apl("1+'A") == Lines{"SYNTAX ERROR", "      1+'A", "        ^"});
}

TEST_CASE("assignment shows nothing; a value in parentheses or through ⎕← is shown") {
  Apl a;
  CHECK(a("X←2+3") == Lines{});
  CHECK(a("X") == Lines{"5"});
  CHECK(a("(Y←4)") == Lines{"4"});
  CHECK(a("⍋V←3 1 2") == Lines{"2 3 1"});
  CHECK(a("V") == Lines{"3 1 2"});
  CHECK(a("1+⎕←2") == Lines{"2", "3"});
  CHECK(a("x") == Lines{"5"});  // names are capitals whatever the case typed
  CHECK(a("A←B←7") == Lines{});
  CHECK(a("A+B") == Lines{"14"});
  CHECK(a("X←3 ⍝ a trailing comment") == Lines{});
  CHECK(a("⍝ a comment line") == Lines{});
  CHECK(a("") == Lines{});
  CHECK(a("X") == Lines{"3"});
}

TEST_CASE("a statement that fails keeps what it assigned before the failure (APL\\360)") {
  Apl a;
  a("X←5");
  a("V←1 2 3");
  CHECK(a("(X←7)+'A'")[0] == "DOMAIN ERROR");  // X←7 ran before + failed
  CHECK(a("X") == Lines{"7"});
  CHECK(a("(V[1]←0)+'A'")[0] == "DOMAIN ERROR");
  CHECK(a("V") == Lines{"0 2 3"});
  CHECK(a("Z←(W←1)÷0")[0] == "DOMAIN ERROR");
  CHECK(a("W") == Lines{"1"});
  CHECK(a("Z")[0] == "VALUE ERROR");
  CHECK(a("(⎕IO←0)+'A'")[0] == "DOMAIN ERROR");
  CHECK(a("⎕IO") == Lines{"0"});
  // Within the statement, an assignment is seen by what follows it (right to left).
  CHECK(a("X+X←10") == Lines{"20"});
  CHECK(a("X") == Lines{"10"});
}

TEST_CASE("the host's names: read through get, checked and set when assigned") {
  Apl a;
  a.host.owned["INPPN"] = Value::of_numbers({2, 3}, std::vector<double>{1, 2, 3, 4, 5, 6});
  a.host.owned["IMAGE"] = std::nullopt;
  CHECK(a("INPPN[2;]") == Lines{"4 5 6"});
  CHECK(a("⍴INPPN") == Lines{"2 3"});
  CHECK(a("IMAGE")[0] == "VALUE ERROR");
  CHECK(a("(INPPN[1;1]←100)+'A'")[0] == "DOMAIN ERROR");
  CHECK(a.host.checked == std::vector<std::string>{"INPPN"});
  CHECK(a.host.set_names == std::vector<std::string>{"INPPN"});
  CHECK(a.host.owned["INPPN"]->numbers()[0] == 100);
  CHECK(a("INPPN[1;]") == Lines{"100 2 3"});
  a.host.refused = "INPPN";
  CHECK(a("INPPN←0")[0] == "DOMAIN ERROR");
  CHECK(a("INPPN[1;1]←0")[0] == "DOMAIN ERROR");
  CHECK(a.host.owned["INPPN"]->numbers()[0] == 100);
  CHECK(a.host.set_names == std::vector<std::string>{"INPPN"});
  CHECK(a(")VARS") == Lines{"INPPN"});
  a("X←1");
  CHECK(a(")VARS") == Lines{"X", "INPPN"});
  CHECK(a(")ERASE INPPN X") == Lines{"NOT ERASED: INPPN"});
  CHECK(a(")VARS") == Lines{"INPPN"});
}

TEST_CASE("native functions: niladic, monadic, dyadic; their reports") {
  Apl a;
  a.session.define_native(
      "TWICE", 1,
      [](const Value*, const Value* r) -> std::optional<Value> {
        Value v = *r;
        for (auto& x : v.mutable_numbers()) x *= 2;
        return v;
      },
      "TWICE X: X doubled.");
  a.session.define_native("JOIN", 2, [](const Value* l, const Value* r) -> std::optional<Value> {
    return Value::text(l->utf8() + r->utf8());
  });
  a.session.define_native("NOTHING", 0,
                          [](const Value*, const Value*) -> std::optional<Value> { return {}; });
  a.session.define_native("FAIL", 1, [](const Value*, const Value*) -> std::optional<Value> {
    throw std::runtime_error("INCORRECT ENTRY: NO SURFACE");
  });
  CHECK(a("TWICE 1 2 3") == Lines{"2 4 6"});
  CHECK(a("1+TWICE 3") == Lines{"7"});
  CHECK(a("'AB' JOIN 'CD'") == Lines{"ABCD"});
  CHECK(a("NOTHING") == Lines{});
  CHECK(a("X←NOTHING") == Lines{"VALUE ERROR", "      X←NOTHING", "        ^"});
  CHECK(a("FAIL 1") == Lines{"INCORRECT ENTRY: NO SURFACE", "      FAIL 1", "      ^"});
  CHECK(a("TWICE") == Lines{"SYNTAX ERROR", "      TWICE", "      ^"});
  CHECK(a("TWICE←3")[0] == "SYNTAX ERROR");
  CHECK(a(")FNS") == Lines{"FAIL JOIN NOTHING START TWICE"});  // all the host's: no heading
  CHECK(a.session.function_help("twice") == "TWICE X: X doubled.");
  CHECK(a.session.function_names() ==
        std::vector<std::string>{"FAIL", "JOIN", "NOTHING", "START", "TWICE"});
  CHECK_THROWS_AS(a.session.define_native("2X", 1, {}), Error);
}

TEST_CASE("START and )OFF say where the dialogue goes") {
  Apl a;
  a("X←1");
  CHECK(a.next == AplSession::Next::stay);
  a("START");
  CHECK(a.next == AplSession::Next::start);
  a(")OFF");
  CHECK(a.next == AplSession::Next::off);
  a("∇GO");
  a("X←2");
  a("START∇");
  a("GO");
  CHECK(a.next == AplSession::Next::start);
  CHECK(a("X") == Lines{"2"});
  CHECK(a.next == AplSession::Next::stay);
}

TEST_CASE("⎕ output and evaluated input; ⍞ character input") {
  Apl a;
  a.host.input = {"2+3"};
  CHECK(a("X←⎕") == Lines{"⎕:"});
  CHECK(a.host.prompts == std::vector<std::string>{"      "});
  CHECK(a("X") == Lines{"5"});
  a.host.input = {"", "1÷0", "X×2"};
  CHECK(a("Y←⎕") == Lines{"⎕:", "⎕:", "DOMAIN ERROR", "      1÷0", "       ^", "⎕:"});
  CHECK(a("Y") == Lines{"10"});
  a.host.input = {"→"};
  CHECK(a("Y←1+⎕") == Lines{"⎕:"});  // → abandons the statement
  CHECK(a("Y") == Lines{"10"});
  CHECK(a("Y←⎕") == Lines{"⎕:", "INTERRUPT", "      Y←⎕", "        ^"});  // no more input
  a.host.input = {"HELLO, WORLD"};
  a.host.prompts.clear();
  CHECK(a("T←⍞") == Lines{});
  CHECK(a("⍴T") == Lines{"12"});
  a.host.input = {"ME"};
  CHECK(a("⍞←'NAME: '") == Lines{"NAME: "});
  a("∇ASK");
  a("⍞←'NAME: '");
  a("N←⍞∇");
  a.host.prompts.clear();
  CHECK(a("ASK") == Lines{});
  CHECK(a.host.prompts == std::vector<std::string>{"NAME: "});
  CHECK(a("N") == Lines{"ME"});
}

TEST_CASE("system commands") {
  Apl a;
  a("B←1");
  a("A←2");
  a("∇Z←F X");
  a("Z←X∇");
  CHECK(a(")VARS") == Lines{"A B"});
  CHECK(a(")VARS B") == Lines{"B"});
  CHECK(a(")FNS") == Lines{"F", "START"});  // the session's own, then the host's
  CHECK(a(")ERASE A F Q") == Lines{"NOT ERASED: Q"});
  CHECK(a(")VARS") == Lines{"B"});
  CHECK(a(")FNS") == Lines{"START"});
  CHECK(a(")ORIGIN 0") == Lines{"WAS 1"});
  CHECK(a("⍳2") == Lines{"0 1"});
  CHECK(a(")ORIGIN 2") == Lines{"INCORRECT COMMAND"});
  CHECK(a(")SAVE MYWS") == Lines{"SAVED MYWS"});
  CHECK(a.host.saved == "MYWS");
  CHECK(a(")LOAD MYWS") == Lines{"LOADED MYWS"});
  CHECK(a.host.loaded == "MYWS");
  CHECK(a(")CLEAR") == Lines{"CLEAR WS"});
  CHECK(a(")VARS") == Lines{});
  CHECK(a("⎕IO") == Lines{"1"});
  CHECK(a(")NONSENSE") == Lines{"INCORRECT COMMAND"});
  CHECK(a(")vars") == Lines{});
}

TEST_CASE("the session's interface: variables, assignment, origin and precision") {
  Apl a;
  a.session.assign("V", Value::vector({1, 2, 3}));
  CHECK(a("+/V") == Lines{"6"});
  CHECK(a.session.variable("v")->shape() == Shape{3});
  CHECK(!a.session.variable("W"));
  CHECK(a.session.variables().size() == 1);
  CHECK(a.session.erase("V"));
  CHECK(!a.session.erase("V"));
  a.session.set_index_origin(0);
  CHECK(a("⍳2") == Lines{"0 1"});
  CHECK(a.session.index_origin() == 0);
  CHECK_THROWS_AS(a.session.set_index_origin(2), Error);
  a.session.set_print_precision(4);
  CHECK(a("÷3") == Lines{"0.3333"});
  CHECK_THROWS_AS(a.session.assign("START", Value::number(1)), Error);
  CHECK(a.session.prompt() == "      ");
}

TEST_CASE("the default limits stop endless recursion and deep nesting before the stack") {
  Apl a;
  a.run({"∇Z←R N", "Z←1+R N+1∇"});
  CHECK(a("R 1")[0] == "DEPTH ERROR");
  CHECK(a(")SI").size() == 999);  // every call of R waits on the state indicator (one line)
  CHECK(a("→") == Lines{});
  a.run({"∇Z←FACT N", "Z←1", "→(N≤1)/0", "Z←N×FACT N-1∇"});
  CHECK(a("FACT 150") == Lines{"5.713383956E262"});
  std::string deep(3000, '(');
  deep += "1";
  deep += std::string(3000, ')');
  CHECK(a(deep)[0] == "DEPTH ERROR");
  CHECK(a("⍎'⍎''1+1'''") == Lines{"2"});
}

TEST_CASE("limits: WS FULL, INTERRUPT after the work budget or by the host, DEPTH ERROR") {
  Apl a;
  Limits limits;
  limits.max_elements = 1000;
  limits.max_work = 100000;
  limits.max_depth = 60;
  a.session.set_limits(limits);
  CHECK(a("⍴⍳1000") == Lines{"1000"});
  CHECK(a("⍳1001")[0] == "WS FULL");
  CHECK(a("⍴(⍳40)∘.+⍳40")[0] == "WS FULL");
  CHECK(a("1E9⍴1")[0] == "WS FULL");
  a("∇LOOP");
  a("L:→L∇");
  CHECK(a("LOOP") == Lines{"INTERRUPT", "LOOP[1] L:→L", "        ^"});
  CHECK(a(")SIC") == Lines{});
  a("∇Z←R N");
  a("Z←R N+1∇");
  CHECK(a("R 1")[0] == "DEPTH ERROR");
  CHECK(a("1+1") == Lines{"2"});        // a line typed runs whatever the state indicator holds
  CHECK(a("R 1")[0] == "DEPTH ERROR");  // but no function can be called
  CHECK(a(")SIC") == Lines{});
  CHECK(a("1+1") == Lines{"2"});
}

TEST_CASE("Ctrl-C: INTERRUPT where the work stopped, the function suspended, the Ctrl-C read") {
  igds::block_interrupts();
  Apl a;
  a.run({"∇LOOP", "L:→L∇"});
  REQUIRE(::kill(::getpid(), SIGINT) == 0);
  CHECK(a("LOOP") == Lines{"INTERRUPT", "LOOP[1] L:→L", "        ^"});
  CHECK_FALSE(igds::interrupt_pending());
  CHECK(a(")SI") == Lines{"LOOP[1] *"});
  CHECK(a("1+1") == Lines{"2"});
  CHECK(a(")SIC") == Lines{});
  // Inside a long primitive: a product of two 600 x 600 matrices stops between its blocks. SIG
  // sends the Ctrl-C after the statement looked for one.
  a.session.define_native("SIG", 1, [](const Value*, const Value* b) -> std::optional<Value> {
    ::kill(::getpid(), SIGINT);
    return *b;
  });
  a("A←600 600⍴⍳7");
  CHECK(a("⍴A+.×A") == Lines{"600 600"});
  CHECK(a("⍴A+.×SIG A") == Lines{"INTERRUPT", "      ⍴A+.×SIG A", "        ^"});
  CHECK_FALSE(igds::interrupt_pending());
  CHECK(a("1+1") == Lines{"2"});
}

}  // namespace igds::apl::test

namespace igds::apl::test {

TEST_CASE("⎕PW and )WIDTH: longer lines go on, indented six, numbers never cut") {
  Apl a;
  const Lines wide = a("⍳40");
  REQUIRE(wide.size() == 2);
  CHECK(wide[0].size() == 80);
  CHECK(wide[1] == "      31 32 33 34 35 36 37 38 39 40");
  CHECK(a(")WIDTH 30") == Lines{"WAS 80"});
  CHECK(a("⎕PW") == Lines{"30"});
  CHECK(a("⍳20") == Lines{"1 2 3 4 5 6 7 8 9 10 11 12 13", "      14 15 16 17 18 19 20"});
  // A matrix breaks at the same column in every row, so its columns stay aligned.
  CHECK(a("2 12⍴⍳24") == Lines{" 1  2  3  4  5  6  7  8  9 10", "      11 12",
                               "13 14 15 16 17 18 19 20 21 22", "      23 24"});
  // Characters break at the width.
  CHECK(a("40⍴'ABCDEFGHIJ'") == Lines{"ABCDEFGHIJABCDEFGHIJABCDEFGHIJ", "      ABCDEFGHIJ"});
  CHECK(a("⎕PW←29")[0] == "DOMAIN ERROR");
  CHECK(a(")WIDTH 255") == Lines{"INCORRECT COMMAND"});
  CHECK(a(")WIDTH") == Lines{"IS 30"});
  a("⎕PW←254");
  CHECK(a("⍳40").size() == 1);
  a.session.set_print_width(40);
  CHECK(a.session.print_width() == 40);
  CHECK(a(")CLEAR") == Lines{"CLEAR WS"});
  CHECK(a("⎕PW") == Lines{"80"});
}

TEST_CASE("an undefined name beside a value is VALUE ERROR, as APL\\360 reads it") {
  CHECK(apl("FOO 3") == Lines{"VALUE ERROR", "      FOO 3", "      ^"});
  CHECK(apl("3 FOO") == Lines{"VALUE ERROR", "      3 FOO", "        ^"});
  CHECK(apl("2 3") == Lines{"2 3"});
  Apl a;
  a("X←1");
  CHECK(a("X 2")[0] == "SYNTAX ERROR");
  CHECK(a("X FOO")[0] == "VALUE ERROR");
  a.run({"∇F", "FOO 3∇"});
  CHECK(a("F") == Lines{"VALUE ERROR", "F[1] FOO 3", "     ^"});
}

TEST_CASE("the system functions and variables an APL\\360 user reaches for") {
  Apl a;
  a("X←1");
  a.run({"∇Z←F Y", "Z←Y+1∇"});
  CHECK(a("⎕NC 'X'") == Lines{"2"});
  CHECK(a("⎕NC 'F'") == Lines{"3"});
  CHECK(a("⎕NC 'NOTHING'") == Lines{"0"});
  CHECK(a("⎕NC '2X'") == Lines{"4"});
  CHECK(a("⎕NC 3 7⍴'X      F      START  '") == Lines{"2 3 3"});
  CHECK(a("⎕CR 'F'") == Lines{"Z←F Y", "Z←Y+1"});
  CHECK(a("⍴⎕CR 'F'") == Lines{"2 5"});
  CHECK(a("⍴⎕CR 'X'") == Lines{"0 0"});
  CHECK(a("⎕FX 2 5⍴'Z←G YZ←Y×2'") == Lines{"G"});
  CHECK(a("G 4") == Lines{"8"});
  CHECK(a("⎕FX 2 5⍴'Z←X YZ←Y×2'") == Lines{"1"});  // X is a variable
  CHECK(a("⎕FX ⎕CR 'F'") == Lines{"F"});
  CHECK(a("⎕EX 'X'") == Lines{"1"});
  CHECK(a("X")[0] == "VALUE ERROR");
  CHECK(a("⎕EX 'G'") == Lines{"1"});
  CHECK(a("⎕NC 'G'") == Lines{"0"});
  CHECK(a("⎕EX 'START'") == Lines{"0"});  // the host's function stays
  // A local is classified and expunged where the statement runs (right to left).
  a.run({"∇Z←L;V", "V←1", "Z←(⎕NC 'M'),(⎕EX 'V'),⎕NC 'V'", "M:Z←Z,⎕NC 'V'∇"});
  CHECK(a("L") == Lines{"1 1 2 0"});
  CHECK(a("⍴⎕TS") == Lines{"7"});
  CHECK(a("(1↑⎕TS)>2000") == Lines{"1"});
  CHECK(a("⍴⎕AI") == Lines{"4"});
  CHECK(a("⎕AV[⎕AV⍳'A⍴¯']") == Lines{"A⍴¯"});
  CHECK(a("(⍴⎕AV)≥⌈/⎕AV⍳'⍝⍞∇∆⍙⌹'") == Lines{"1"});
  CHECK(a("⎕TS←1")[0] == "SYNTAX ERROR");
  CHECK(a("⎕EX←1")[0] == "SYNTAX ERROR");
  CHECK(a("1 ⎕EX 'X'")[0] == "SYNTAX ERROR");
}

TEST_CASE("⎕ input that calls a failing function: the function is suspended under the ⎕") {
  Apl a;
  a.run({"∇Z←INV N", "Z←÷N∇"});
  a.host.input = {"INV 0"};
  CHECK(a("X←1+⎕") == Lines{"⎕:", "DOMAIN ERROR", "INV[1] Z←÷N", "         ^"});
  CHECK(a(")SI") == Lines{"INV[1] *"});
  a("N←4");
  CHECK(a("→1") == Lines{});
  CHECK(a("X") == Lines{"1.25"});
}

TEST_CASE("a label is a constant") {
  Apl a;
  a.run({"∇F", "L:L←2∇"});
  CHECK(a("F") == Lines{"SYNTAX ERROR", "F[1] L:L←2", "       ^"});
}

}  // namespace igds::apl::test
