// Defined functions and the ∇ editor (APL\360 User's Manual, chapter 5): headers, local names
// (seen by the functions called, dynamic scope), labels and branches, the line editor.
#include <doctest/doctest.h>

#include "apl_support.h"

namespace igds::apl::test {

TEST_CASE("headers: result or none, no, one or two arguments") {
  Apl a;
  a.run({"∇Z←A PLUS B", "Z←A+B", "∇"});
  CHECK(a("3 PLUS 4") == Lines{"7"});
  CHECK(a("1 PLUS 2 PLUS 3") == Lines{"6"});
  a.run({"∇Z←PI", "Z←○1∇"});
  CHECK(a("PI×2") == Lines{"6.283185307"});
  a.run({"∇SHOW X", "⎕←X×2∇"});
  CHECK(a("SHOW 3") == Lines{"6"});
  CHECK(a("Y←SHOW 3") == Lines{"6", "VALUE ERROR", "      Y←SHOW 3", "        ^"});
  CHECK(a("PLUS 3")[0] == "SYNTAX ERROR");
  CHECK(a("1 SHOW 2")[0] == "SYNTAX ERROR");
  a.run({"∇Z←NORESULT", "X←1∇"});
  CHECK(a("1+NORESULT")[0] == "VALUE ERROR");
}

TEST_CASE("local names hide global ones while the function runs") {
  Apl a;
  a("X←'GLOBAL'");
  a.run({"∇Z←F N;X", "X←N×2", "Z←X+1∇"});
  CHECK(a("F 3") == Lines{"7"});
  CHECK(a("X") == Lines{"GLOBAL"});
  CHECK(a(")VARS") == Lines{"X"});
}

TEST_CASE("dynamic scope: a function sees the local names of the functions that called it") {
  Apl a;
  a.run({"∇Z←OUTER N;T", "T←N×10", "Z←INNER 1∇"});
  a.run({"∇Z←INNER N", "Z←T+N∇"});
  CHECK(a("OUTER 2") == Lines{"21"});
  CHECK(a("INNER 1") == Lines{"VALUE ERROR", "INNER[1] Z←T+N", "           ^"});
}

TEST_CASE("labels and branches: loops, leaving with →0 or a line that is not there") {
  Apl a;
  a.run({"∇Z←SUM N;I", "Z←0", "I←1", "L:→(I>N)/0", "Z←Z+I", "I←I+1", "→L∇"});
  CHECK(a("SUM 10") == Lines{"55"});
  CHECK(a("SUM 0") == Lines{"0"});
  a.run({"∇Z←FACT N", "→(N>1)/REC", "Z←1", "→0", "REC:Z←N×FACT N-1∇"});
  CHECK(a("FACT 10") == Lines{"3628800"});
  a.run({"∇Z←AWAY", "Z←1", "→99", "Z←2∇"});
  CHECK(a("AWAY") == Lines{"1"});
  a.run({"∇Z←EMPTY", "Z←1", "→⍳0", "Z←2∇"});
  CHECK(a("EMPTY") == Lines{"2"});  // → of an empty vector goes on to the next line
  a.run({"∇Z←CHAR", "→'A'∇"});
  CHECK(a("CHAR")[0] == "DOMAIN ERROR");
  a("L←5");
  CHECK(a("SUM 3") == Lines{"6"});  // the label L is local to SUM
  CHECK(a("L") == Lines{"5"});
}

TEST_CASE("an error in a function: its line with a caret; what it assigned before stays") {
  Apl a;
  a("X←1");
  a.run({"∇BAD", "X←2", "1÷0∇"});
  CHECK(a("BAD") == Lines{"DOMAIN ERROR", "BAD[2] 1÷0", "        ^"});
  CHECK(a("X") == Lines{"2"});
  CHECK(a(")SIC") == Lines{});
  a.run({"∇Z←CALLER", "Z←BAD∇"});
  CHECK(a("CALLER") == Lines{"DOMAIN ERROR", "BAD[2] 1÷0", "        ^"});
  CHECK(a(")SI") == Lines{"BAD[2] *", "CALLER[1]"});
  CHECK(a("→") == Lines{});
  CHECK(a(")SI") == Lines{});
  a.run({"∇Q", "→∇"});
  CHECK(a("Q") == Lines{});  // → alone abandons all
}

TEST_CASE("the state indicator: a suspended function, its locals, →N to resume, → to clear") {
  Apl a;
  a.run({"∇Z←DIV N;K", "K←10", "Z←K÷N", "Z←Z+1∇"});
  a.run({"∇R←TWICE N", "R←2×DIV N∇"});
  CHECK(a("TWICE 0") == Lines{"DOMAIN ERROR", "DIV[2] Z←K÷N", "          ^"});
  CHECK(a(")SI") == Lines{"DIV[2] *", "TWICE[1]"});
  CHECK(a("⎕LC") == Lines{"2 1"});
  // The suspended function's locals are the names at the prompt.
  CHECK(a("K,N") == Lines{"10 0"});
  CHECK(a("K") == Lines{"10"});
  a("N←5");
  // →2 runs line 2 again, now with N←5: DIV ends, TWICE goes on from where it was.
  CHECK(a("→2") == Lines{"6"});
  CHECK(a(")SI") == Lines{});
  CHECK(a("K")[0] == "VALUE ERROR");
  // →⎕LC resumes at the line that failed; an error in a line typed at a suspension suspends too.
  CHECK(a("DIV 0")[0] == "DOMAIN ERROR");
  CHECK(a("DIV 0")[0] == "DOMAIN ERROR");
  CHECK(a(")SI") == Lines{"DIV[2] *", "DIV[2] *"});
  CHECK(a("→") == Lines{});
  CHECK(a(")SI") == Lines{"DIV[2] *"});
  a("N←1");
  CHECK(a("→⎕LC") == Lines{"11"});
  CHECK(a(")SI") == Lines{});
  // →N with nothing suspended does nothing; an empty branch neither.
  CHECK(a("→3") == Lines{});
  CHECK(a("→⍳0") == Lines{});
}

TEST_CASE("a suspended function can be edited and resumed; a pendent one cannot be changed") {
  Apl a;
  a.run({"∇Z←DIV N", "Z←10÷N∇"});
  a.run({"∇R←TWICE N", "R←2×DIV N∇"});
  CHECK(a("TWICE 0")[0] == "DOMAIN ERROR");
  CHECK(a("∇DIV[1] Z←10÷N+1∇") == Lines{});
  CHECK(a("∇TWICE[1] R←3×DIV N∇") == Lines{"DEFN ERROR"});  // TWICE waits for DIV
  CHECK(!a.session.defining());
  CHECK(a("→1") == Lines{"20"});
  CHECK(a("∇TWICE[1] R←3×DIV N∇") == Lines{});
  CHECK(a("TWICE 1") == Lines{"15"});
}

TEST_CASE("the header of a suspended function cannot change; its locals stay visible") {
  Apl a;
  a.run({"∇F;X", "X←1", "÷0∇"});
  CHECK(a("F")[0] == "DOMAIN ERROR");
  CHECK(a("∇F[0] F;X;Y∇") == Lines{"DEFN ERROR"});
  CHECK(a.session.defining());  // open, to be mended
  CHECK(a("[0] F;X∇") == Lines{});
  CHECK(a("X") == Lines{"1"});
  CHECK(a("X←7") == Lines{});
  CHECK(a("X") == Lines{"7"});
  CHECK(a(")SIC") == Lines{});
  CHECK(a("X").at(0) == "VALUE ERROR");
}

TEST_CASE("local system variables are given back when the function ends") {
  Apl a;
  a.run({"∇Z←G;⎕IO", "⎕IO←0", "Z←⍳3∇"});
  CHECK(a("G") == Lines{"0 1 2"});
  CHECK(a("⎕IO") == Lines{"1"});
  a.run({"∇Z←H", "Z←⎕LC∇"});
  CHECK(a("H") == Lines{"1"});
}

TEST_CASE("the editor: prompts, replacing, inserting, listing, deleting, closing") {
  Apl a;
  CHECK(a.session.prompt() == "      ");
  a("∇Z←A F B");
  CHECK(a.session.defining());
  CHECK(a.session.prompt() == "[1] ");
  a("Z←A+B");
  CHECK(a.session.prompt() == "[2] ");
  CHECK(a("[⎕]") == Lines{"    ∇Z←A F B", "[1]  Z←A+B", "    ∇"});
  CHECK(a.session.prompt() == "[2] ");
  a("[0.5] ⍝ ADDS");
  CHECK(a.session.prompt() == "[0.6] ");
  CHECK(a("[⎕]") == Lines{"    ∇Z←A F B", "[0.5]  ⍝ ADDS", "[1]  Z←A+B", "    ∇"});
  a("[1] Z←A-B");
  CHECK(a("[1⎕]") == Lines{"[1]  Z←A-B"});
  CHECK(a.session.prompt() == "[1] ");
  a("[2]");
  CHECK(a.session.prompt() == "[2] ");
  a("Z←Z×10");
  CHECK(a("[⎕2]") == Lines{"[2]  Z←Z×10", "    ∇"});
  a("[∆0.5]");
  a("∇");
  CHECK(!a.session.defining());
  CHECK(a("5 F 3") == Lines{"20"});
  a("∇F");
  CHECK(a.session.prompt() == "[3] ");
  CHECK(a("[⎕]∇") == Lines{"    ∇Z←A F B", "[1]  Z←A-B", "[2]  Z←Z×10", "    ∇"});
  CHECK(!a.session.defining());
  CHECK(a("∇F[⎕]∇") == Lines{"    ∇Z←A F B", "[1]  Z←A-B", "[2]  Z←Z×10", "    ∇"});
  a("∇F[2]Z←Z×100∇");
  CHECK(a("5 F 3") == Lines{"200"});
}

TEST_CASE("the editor: the header at line 0, and DEFN ERROR") {
  Apl a;
  a.run({"∇Z←A F B", "Z←A+B∇"});
  a.run({"∇F", "[0] Z←A G B", "∇"});
  CHECK(a(")FNS") == Lines{"F G", "START"});
  CHECK(a("1 G 2") == Lines{"3"});
  a("X←1");
  CHECK(a("∇X") == Lines{"DEFN ERROR"});
  CHECK(a("∇Z←A F B") == Lines{"DEFN ERROR"});
  CHECK(a("∇Z←") == Lines{"DEFN ERROR"});
  CHECK(a("∇Z←A B C D") == Lines{"DEFN ERROR"});
  CHECK(a("∇Z←F Z") == Lines{"DEFN ERROR"});
  CHECK(a("∇START") == Lines{"DEFN ERROR"});
  CHECK(!a.session.defining());
  a("∇H");
  CHECK(a("[X]") == Lines{"DEFN ERROR"});
  CHECK(a("[0] 1+") == Lines{"DEFN ERROR"});
  a("L:1");
  CHECK(a("L:2∇") == Lines{"DEFN ERROR"});  // two labels L: the definition stays open
  CHECK(a.session.defining());
  CHECK(a("[2] M:2∇") == Lines{});
  CHECK(!a.session.defining());
}

TEST_CASE("functions kept by the host and defined again") {
  Apl a;
  a.run({"∇Z←A PLUS B", "Z←A+B∇"});
  a.run({"∇Z←TWICE X", "Z←X PLUS X∇"});
  auto sources = a.session.defined_functions();
  REQUIRE(sources.size() == 2);
  CHECK(sources[0] == std::vector<std::string>{"Z←A PLUS B", "Z←A+B"});
  Apl b;
  for (const auto& s : sources) b.session.define_function(s);
  CHECK(b("TWICE 4") == Lines{"8"});
  CHECK_THROWS_AS(b.session.define_function({"Z←A B C D"}), Error);
  b("Y←1");
  CHECK_THROWS_AS(b.session.define_function({"Y", "1"}), Error);
  b.session.define_function({"∇Z←TWICE X", "Z←3×X"});
  CHECK(b("TWICE 4") == Lines{"12"});
}

TEST_CASE("a loop over a host's array, element by element") {
  Apl a;
  a.host.owned["INTPN"] = Value::of_numbers({4, 3}, std::vector<double>(12, 1.0));
  a.run({"∇Z←TOTAL;I", "Z←0", "I←0", "L:→(I≥1↑⍴INTPN)/0", "I←I+1", "INTPN[I;3]←INTPN[I;3]+I",
         "Z←Z+INTPN[I;3]", "→L∇"});
  CHECK(a("TOTAL") == Lines{"14"});
  CHECK(a("INTPN[;3]") == Lines{"2 3 4 5"});
  CHECK(a.host.set_names == std::vector<std::string>(4, "INTPN"));
}

}  // namespace igds::apl::test

namespace igds::apl::test {

TEST_CASE("a statement of a function that is not an assignment shows its value") {
  Apl a;
  a.run({"∇G", "5", "X←6", "(Y←7)", "⍎'X'", "⍎'Z←8'∇"});
  CHECK(a("G") == Lines{"5", "7", "6"});
}

TEST_CASE("[n⎕m]: the line shown, marks under it delete and insert, the next line laid over it") {
  Apl a;
  a.run({"∇Z←F X", "Z←X+1"});
  // Position 8 of "[1] Z←X+1" is the +: / deletes it, 1 under the 1 inserts one blank before it.
  CHECK(a("[1⎕8]") == Lines{"[1] Z←X+1"});
  CHECK(a.session.prompt() == std::string(7, ' '));
  CHECK(a("/1") == Lines{"[1] Z←X 1"});
  CHECK(a.session.prompt() == std::string(7, ' '));  // at the inserted blank
  CHECK(a("×") == Lines{});
  CHECK(a.session.prompt() == "[2] ");
  CHECK(a("[⎕]∇") == Lines{"    ∇Z←F X", "[1]  Z←X×1", "    ∇"});
  CHECK(a("F 3") == Lines{"3"});
  // Letters insert five blanks each; a mark under the line number does nothing.
  a("∇F");
  CHECK(a("[1⎕1]") == Lines{"[1] Z←X×1"});
  CHECK(a("////    A") == Lines{"[1] Z←X×     1"});
  CHECK(a.session.prompt() == std::string(8, ' '));
  CHECK(a("(2+2)") == Lines{});
  CHECK(a("[1⎕]") == Lines{"[1]  Z←X×(2+2)1"});
  CHECK(a("[1⎕0]") == Lines{"[1] Z←X×(2+2)1"});
  CHECK(a("             /") == Lines{"[1] Z←X×(2+2)"});  // no insertion: typed on at the end
  CHECK(a.session.prompt() == std::string(13, ' '));
  CHECK(a("+1∇") == Lines{});  // a closing ∇ ends the definition
  CHECK(!a.session.defining());
  CHECK(a("F 3") == Lines{"15"});
  // A line that does not exist cannot be edited.
  a("∇F");
  CHECK(a("[7⎕1]") == Lines{"DEFN ERROR"});
  CHECK(a("∇") == Lines{});
}

TEST_CASE("∇ at the start of a line closes the definition; `∇G` then opens G") {
  Apl a;
  a.run({"∇Z←F X", "Z←2×X"});
  CHECK(a("∇G") == Lines{});
  CHECK(a.session.prompt() == "[1] ");
  CHECK(a("F 4") == Lines{});  // a line of G
  CHECK(a("∇") == Lines{});
  CHECK(!a.session.defining());
  CHECK(a("F 4") == Lines{"8"});
  CHECK(a("G") == Lines{"8"});
  CHECK(a("∇H") == Lines{});
  CHECK(a("[1] 1+") == Lines{});
  CHECK(a("  ∇") == Lines{});
  CHECK(a("H") == Lines{"SYNTAX ERROR", "H[1] 1+", "      ^"});
}

}  // namespace igds::apl::test

namespace igds::apl::test {

TEST_CASE("the loops' shortcuts give APL's results whatever the arguments") {
  Apl a;
  // Z←Z+I on numbers, then on vectors; →(I<N)/L on numbers, then on a vector test.
  a.run({"∇Z←SUM N;I", "Z←I←0", "L:Z←Z+I", "I←I+1", "→(I<N)/L∇"});
  CHECK(a("SUM 5") == Lines{"10"});
  CHECK(a("SUM 1") == Lines{"0"});
  a.run({"∇Z←VSUM N;I", "Z←0 0", "I←0", "L:Z←Z+I,2×I", "I←I+1", "→(1↑I<N)/L∇"});
  CHECK(a("VSUM 4") == Lines{"6 12"});
  a.run({"∇Z←TWICE;I", "Z←0", "I←0", "L:Z←Z+1", "I←I+1", "→(2×I<2)/L∇"});
  CHECK(a("TWICE") == Lines{"2"});  // two copies of L: still a branch to L
  a.run({"∇Z←ODD;V", "Z←0", "V←1 0 1", "→(0≠+/V)/(2+3)", "Z←99", "Z←Z+1∇"});
  CHECK(a("ODD") == Lines{"1"});
  a.run({"∇Z←NONE", "Z←1", "→(0×Z)/3", "Z←2∇"});
  CHECK(a("NONE") == Lines{"2"});
  a.run({"∇Z←BAD N", "L:Z←Z+N∇"});
  CHECK(a("BAD 1") == Lines{"VALUE ERROR", "BAD[1] L:Z←Z+N", "           ^"});
  a("→");
  a.run({"∇Z←ORDER;X", "X←1", "Z←(X←3)+X∇"});
  CHECK(a("ORDER") == Lines{"4"});  // X on the right is read first
  a.run({"∇Z←LEN;A", "A←1 2", "Z←A+1 2 3∇"});
  CHECK(a("LEN") == Lines{"LENGTH ERROR", "LEN[2] Z←A+1 2 3", "          ^"});
  a("→");
  a.run({"∇Z←CH;I", "I←'A'", "→(I='A')/3", "Z←1", "Z←2∇"});
  CHECK(a("CH") == Lines{"2"});
  // →N/L with both where they are (a name, a label, a number): nothing computed before the
  // branch.
  a.run({"∇Z←SKIP N", "Z←1", "→N/L", "Z←2", "L:Z←Z+10∇"});
  CHECK(a("SKIP 1") == Lines{"11"});
  CHECK(a("SKIP 0") == Lines{"12"});
  a.run({"∇Z←OUT N", "Z←1", "→(N)/0", "Z←2∇"});
  CHECK(a("OUT 100") == Lines{"1"});
  CHECK(a("OUT 0") == Lines{"2"});
}

}  // namespace igds::apl::test
