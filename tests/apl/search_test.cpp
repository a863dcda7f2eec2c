// Index generator and index of, membership, without, grades, deal, decode and encode, matrix
// inverse and divide, execute (APL\360 User's Manual, chapter 3; APL.SV for execute and the
// collating grade; APL2 Language Reference for without).
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "apl_support.h"

namespace igds::apl::test {

TEST_CASE("index generator and index of, in ⎕IO 1 and 0") {
  CHECK(first("⍳5") == "1 2 3 4 5");
  CHECK(first("⍴⍳0") == "0");
  CHECK(first("⍳0") == "");
  CHECK(first("⍳¯1") == "DOMAIN ERROR");
  CHECK(first("⍳2.5") == "DOMAIN ERROR");
  CHECK(first("'ABCD'⍳'DA'") == "4 1");
  CHECK(first("1 2 3⍳4") == "4");
  CHECK(first("5 1 5⍳5") == "1");
  CHECK(apl("3 1 4⍳2 2⍴1 3 4 9") == Lines{"2 1", "3 4"});
  CHECK(first("1 2 3⍳'A'") == "4");
  CHECK(first("1 2 3⍳1+1E¯14") == "1");  // the comparison tolerance
  CHECK(first("(2 2⍴1)⍳1") == "RANK ERROR");
  Apl a;
  a("⎕IO←0");
  CHECK(a("⍳3") == Lines{"0 1 2"});
  CHECK(a("1 2 3⍳4 2") == Lines{"3 1"});
}

TEST_CASE("index of and membership on long lists (searched by sorting)") {
  Apl a;
  a("L←⌽⍳1000");
  CHECK(a("L⍳1 1000 500 0") == Lines{"1000 1 501 1001"});
  CHECK(a("+/(⍳2000)∊L") == Lines{"1000"});
  CHECK(a("(L,L)⍳7") == Lines{"994"});
  CHECK(a("L⍳7+1E¯14") == Lines{"994"});
  a("C←'THE QUICK BROWN FOX JUMPS OVER THE LAZY DOG'");
  CHECK(a("C⍳'QZX'") == Lines{"5 38 19"});
}

TEST_CASE("membership and without") {
  CHECK(first("2 5∊1 2 3") == "1 0");
  CHECK(first("'AB'∊'ABC'") == "1 1");
  CHECK(first("3∊'3'") == "0");
  CHECK(apl("(2 2⍴⍳4)∊2 3") == Lines{"0 1", "1 0"});
  CHECK(first("⍴5∊⍳0") == "");
  CHECK(first("1 2 3 4~2 4") == "1 3");
  CHECK(first("'HELLO'~'L'") == "HEO");
  CHECK(first("⍴(⍳3)~⍳3") == "0");
}

TEST_CASE("grades: the indices that order B, equal items in their order") {
  CHECK(first("⍋3 1 2") == "2 3 1");
  CHECK(first("⍒3 1 2") == "1 3 2");
  CHECK(first("⍋2 1 2 1") == "2 4 1 3");
  CHECK(first("⍒2 1 2 1") == "1 3 2 4");
  CHECK(first("⍋'BCA'") == "3 1 2");
  CHECK(first("⍋3 2⍴1 2 1 1 0 5") == "3 2 1");  // rows compared left to right
  CHECK(first("⍋⍳0") == "");
  CHECK(first("⍋5") == "RANK ERROR");
  CHECK(first("'CBA'⍋'ABCA'") == "3 2 1 4");
  CHECK(first("'AB'⍋'XBA'") == "3 2 1");  // absent from A: after all of A
  CHECK(first("1 2⍋3 1") == "DOMAIN ERROR");
  Apl a;
  a("⎕IO←0");
  CHECK(a("⍋3 1 2") == Lines{"1 2 0"});
}

TEST_CASE("deal: A different integers from ⍳B") {
  Apl a;
  CHECK(a("⍴3?10") == Lines{"3"});
  CHECK(a("∧/(⍳10)∊10?10") == Lines{"1"});
  CHECK(a("X←5?1000000000") == Lines{});
  CHECK(a("(∧/X≥1)∧(∧/X≤1E9)∧5=+/,X∘.=X") == Lines{"1"});
  CHECK(a("⍴0?0") == Lines{"0"});
  CHECK(a("11?10")[0] == "DOMAIN ERROR");
  CHECK(a("1 2?10")[0] == "LENGTH ERROR");
}

TEST_CASE("decode: the value of digits B in the number system A") {
  CHECK(first("10⊥1 2 3") == "123");
  CHECK(first("2⊥1 0 1") == "5");
  CHECK(first("24 60 60⊥1 2 3") == "3723");
  CHECK(first("1 2 3⊥4 5 6") == "45");
  CHECK(first("2⊥3 2⍴1 0 1 1 0 1") == "6 3");
  CHECK(first("10⊥⍳0") == "0");
  CHECK(first("10⊥5") == "5");
  CHECK(first("1 2⊥1 2 3") == "LENGTH ERROR");
  CHECK(apl("(2 3⍴2 2 2 10 10 10)⊥3 2⍴1 0 0 1 1 1") == Lines{"  5  3", "101 11"});
}

TEST_CASE("encode: the digits of B in the number system A") {
  CHECK(first("2 2 2⊤5") == "1 0 1");
  CHECK(first("24 60 60⊤3723") == "1 2 3");
  CHECK(first("0 24⊤50") == "2 2");
  CHECK(first("10 10⊤123") == "2 3");
  CHECK(apl("2 2 2⊤5 6") == Lines{"1 1", "0 1", "1 0"});
  CHECK(first("2 2⊤¯1") == "1 1");
  CHECK(first("10⊤¯3") == "7");
  CHECK(first("1.5 1⊤2.25") == "0.5 0.25");
}

TEST_CASE("matrix inverse and matrix divide (least squares)") {
  CHECK(apl("⌹2 2⍴2 0 0 4") == Lines{"0.5 0", "0   0.25"});
  CHECK(apl("⌹2 2⍴1 2 3 4") == Lines{"¯2    1", " 1.5 ¯0.5"});
  CHECK(first("⌹4") == "0.25");
  CHECK(first("⌹1 2") == "0.2 0.4");
  CHECK(first("⍴⌹3 2⍴1 2 3 4 5 7") == "2 3");
  // y = a + b×x through (1,4) (2,6) (3,10), least squares: a = 2÷3, b = 3.
  CHECK(first("4 6 10⌹3 2⍴1 1 1 2 1 3") == "0.6666666667 3");
  CHECK(first("8⌹2") == "4");
  CHECK(apl("(2 2⍴1 2 3 4)⌹2 2⍴1 0 0 1") == Lines{"1 2", "3 4"});
  Apl a;
  a("M←3 3⍴4 1 2 1 5 3 2 3 6");
  CHECK(a("∧/,(|(M+.×⌹M)-3 3⍴1 0 0 0)<1E¯12") == Lines{"1"});
  CHECK(a("∧/(|(M+.×(1 2 3⌹M))-1 2 3)<1E¯12") == Lines{"1"});
  CHECK(first("⌹2 2⍴1 2 2 4") == "DOMAIN ERROR");
  CHECK(first("⌹2 3⍴⍳6") == "DOMAIN ERROR");  // more columns than rows
  CHECK(first("1 2⌹3 2⍴⍳6") == "LENGTH ERROR");
  CHECK(first("⌹2 2 2⍴1") == "RANK ERROR");
  CHECK(first("⌹'AB'") == "DOMAIN ERROR");
}

TEST_CASE("execute: the statement of the characters") {
  CHECK(first("⍎'2+3'") == "5");
  CHECK(first("⍴⍎'⍳4'") == "4");
  Apl a;
  CHECK(a("⍎'X←5'") == Lines{});  // an assignment shows nothing
  CHECK(a("X") == Lines{"5"});
  CHECK(a("⍎''") == Lines{});
  CHECK(a("⍎'⍝ nothing'") == Lines{});
  CHECK(a("1+⍎'1÷0'") == Lines{"DOMAIN ERROR", "      1+⍎'1÷0'", "        ^"});
  CHECK(a("⍎2")[0] == "DOMAIN ERROR");
  CHECK(a("⍎2 2⍴'AB'")[0] == "RANK ERROR");
  CHECK(a("⍎'→3'")[0] == "SYNTAX ERROR");
  CHECK(a("Y←⍎'⍳0'") == Lines{});
  CHECK(a("⍴Y") == Lines{"0"});
}

}  // namespace igds::apl::test
