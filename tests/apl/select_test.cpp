// Take, drop, compress, expand, indexing and indexed assignment (APL\360 User's Manual,
// chapter 3; APL2 Language Reference for replicate and the axes of take and drop).
#include <doctest/doctest.h>

#include "apl_support.h"

namespace igds::apl::test {

TEST_CASE("take: from the front, from the end when negative, fill beyond") {
  CHECK(first("2↑1 2 3") == "1 2");
  CHECK(first("¯1↑1 2 3") == "3");
  CHECK(first("¯2↑1 2 3") == "2 3");
  CHECK(first("5↑1 2") == "1 2 0 0 0");
  CHECK(first("¯5↑1 2") == "0 0 0 1 2");
  CHECK(first("4↑'AB'") == "AB  ");
  CHECK(first("¯4↑'AB'") == "  AB");
  CHECK(apl("2 3↑2 2⍴⍳4") == Lines{"1 2 0", "3 4 0"});
  CHECK(apl("¯1 2↑3 3⍴⍳9") == Lines{"7 8"});
  CHECK(first("2↑5") == "5 0");
  CHECK(first("⍴0↑1 2 3") == "0");
  CHECK(apl("2↑[1]3 3⍴⍳9") == Lines{"1 2 3", "4 5 6"});
  CHECK(first("1 2↑1 2 3") == "LENGTH ERROR");
  CHECK(first("1.5↑1 2") == "DOMAIN ERROR");
}

TEST_CASE("drop: all but the first or last elements") {
  CHECK(first("1↓1 2 3") == "2 3");
  CHECK(first("¯1↓1 2 3") == "1 2");
  CHECK(first("⍴5↓1 2") == "0");
  CHECK(first("0↓1 2") == "1 2");
  CHECK(apl("1 1↓3 3⍴⍳9") == Lines{"5 6", "8 9"});
  CHECK(apl("¯1 0↓3 3⍴⍳9") == Lines{"1 2 3", "4 5 6"});
  CHECK(apl("1↓[2]2 3⍴⍳6") == Lines{"2 3", "5 6"});
  CHECK(first("1↓'ABC'") == "BC");
  CHECK(first("1 1↓1 2 3") == "LENGTH ERROR");
}

TEST_CASE("compress and replicate: A[i] copies of item i along the axis") {
  CHECK(first("1 0 1/'ABC'") == "AC");
  CHECK(apl("1 0 1/2 3⍴⍳6") == Lines{"1 3", "4 6"});
  CHECK(apl("1 0⌿2 3⍴⍳6") == Lines{"1 2 3"});
  CHECK(apl("0 1/[1]2 3⍴⍳6") == Lines{"4 5 6"});
  CHECK(first("1/1 2 3") == "1 2 3");
  CHECK(first("⍴0/1 2 3") == "0");
  CHECK(first("3/5") == "5 5 5");
  CHECK(first("2 1/1 2") == "1 1 2");
  CHECK(first("1 ¯2 1/1 2 3") == "1 0 0 3");
  CHECK(first("1 0 1/1 2") == "LENGTH ERROR");
  CHECK(first("1.5/1") == "DOMAIN ERROR");
}

TEST_CASE("expand: B's items where A is 1, fill items where A is 0") {
  CHECK(first("1 0 1\\1 2") == "1 0 2");
  CHECK(first("1 0 1\\'AB'") == "A B");
  CHECK(apl("1 0 1⍀2 3⍴⍳6") == Lines{"1 2 3", "0 0 0", "4 5 6"});
  CHECK(apl("1 0 1 1\\2 3⍴⍳6") == Lines{"1 0 2 3", "4 0 5 6"});
  CHECK(apl("1 0 1\\[1]2 2⍴⍳4") == Lines{"1 2", "0 0", "3 4"});
  CHECK(first("0 1 0\\5") == "0 5 0");
  CHECK(first("1 1\\1 2 3") == "LENGTH ERROR");
  CHECK(first("1 2\\1 2") == "DOMAIN ERROR");
}

TEST_CASE("indexing: the result has the indices' shapes, in order of the axes") {
  CHECK(first("(10×⍳5)[2 4]") == "20 40");
  CHECK(first("'ABCDE'[3]") == "C");
  CHECK(first("⍴'ABCDE'[3]") == "");
  CHECK(apl("'ABC'[2 2⍴1 2 3 1]") == Lines{"AB", "CA"});
  Apl a;
  a("M←3 3⍴⍳9");
  CHECK(a("M[2;3]") == Lines{"6"});
  CHECK(a("M[1 3;]") == Lines{"1 2 3", "7 8 9"});
  CHECK(a("M[;2]") == Lines{"2 5 8"});
  CHECK(a("M[;]") == Lines{"1 2 3", "4 5 6", "7 8 9"});
  CHECK(a("M[3 1;2 2]") == Lines{"8 8", "2 2"});
  CHECK(a("⍴M[⍳0;]") == Lines{"0 3"});
  CHECK(a("M[4;1]")[0] == "INDEX ERROR");
  CHECK(a("M[0;1]")[0] == "INDEX ERROR");
  CHECK(a("M[1]")[0] == "RANK ERROR");
  CHECK(a("M[1.5;1]")[0] == "DOMAIN ERROR");
  CHECK(a("M['A';1]")[0] == "DOMAIN ERROR");
  CHECK(a("5[1]")[0] == "RANK ERROR");
  a("⎕IO←0");
  CHECK(a("M[0;0]") == Lines{"1"});
  CHECK(a("M[2;]") == Lines{"7 8 9"});
  a("A←1+2 3 4⍴⍳24");
  CHECK(a("A[;;0]") == Lines{" 1  5  9", "13 17 21"});
  CHECK(a("A[1;2;3]") == Lines{"24"});
  CHECK(a("A[1;;1 2]") == Lines{"14 15", "18 19", "22 23"});
}

TEST_CASE("indexed assignment: in place, of the same kind, the shapes agreeing") {
  Apl a;
  CHECK(a.run({"V←⍳5", "V[2 4]←0", "V"}) == Lines{"1 0 3 0 5"});
  CHECK(a.run({"V[1 2]←7 8", "V"}) == Lines{"7 8 3 0 5"});
  CHECK(a.run({"M←3 3⍴0", "M[2;]←1 2 3", "M"}) == Lines{"0 0 0", "1 2 3", "0 0 0"});
  CHECK(a.run({"M[1;1 3]←9", "M[1;]"}) == Lines{"9 0 9"});
  CHECK(a.run({"M[;2]←3 1⍴7", "M[;2]"}) == Lines{"7 7 7"});  // unit axes aside, shapes agree
  CHECK(a("V[2]←1 2")[0] == "LENGTH ERROR");
  CHECK(a("V[6]←1")[0] == "INDEX ERROR");
  CHECK(a("V[1]←'A'")[0] == "DOMAIN ERROR");
  CHECK(a("M[1 2;1 2]←1 2 3 4")[0] == "RANK ERROR");
  CHECK(a("V") == Lines{"7 8 3 0 5"});
  CHECK(a("W[1]←1")[0] == "VALUE ERROR");
  CHECK(a.run({"S←'ABC'", "S[2]←'X'", "S"}) == Lines{"AXC"});
  // The value of an indexed assignment is the value assigned.
  CHECK(a("1+V[1]←10") == Lines{"11"});
}

TEST_CASE("a copy is a value: changing one name leaves the other alone") {
  Apl a;
  CHECK(a.run({"A←1 2 3", "B←A", "A[1]←9", "B"}) == Lines{"1 2 3"});
  CHECK(a("A") == Lines{"9 2 3"});
}

}  // namespace igds::apl::test
