// Shape, reshape, ravel, catenate and laminate, reverse, rotate, transpose (APL\360 User's
// Manual, chapter 3; APL2 Language Reference for axes and empty arguments).
#include <doctest/doctest.h>

#include "apl_support.h"

namespace igds::apl::test {

TEST_CASE("shape: the lengths of the axes; a scalar has none") {
  CHECK(first("⍴2 3⍴⍳6") == "2 3");
  CHECK(first("⍴5") == "");
  CHECK(first("⍴⍴5") == "0");
  CHECK(first("⍴'ABC'") == "3");
  CHECK(first("⍴⍴2 3 4⍴0") == "3");
}

TEST_CASE("reshape: the elements of B in order, repeated as needed") {
  CHECK(apl("2 3⍴⍳6") == Lines{"1 2 3", "4 5 6"});
  CHECK(first("5⍴1 2") == "1 2 1 2 1");
  CHECK(apl("2 2⍴'ABCDE'") == Lines{"AB", "CD"});
  CHECK(first("3⍴⍳0") == "0 0 0");  // APL2: an empty B gives fill elements
  CHECK(first("⍴0⍴5") == "0");
  CHECK(first("⍴2 0 3⍴5") == "2 0 3");
  CHECK(first("¯1⍴1") == "DOMAIN ERROR");
  CHECK(first("2.5⍴1") == "DOMAIN ERROR");
  CHECK(first("(2 2⍴1)⍴5") == "RANK ERROR");
  CHECK(first("'A'⍴5") == "DOMAIN ERROR");
}

TEST_CASE("ravel, and ravel with an axis") {
  CHECK(first(",2 2⍴⍳4") == "1 2 3 4");
  CHECK(first("⍴,5") == "1");
  CHECK(first("⍴,[0.5]1 2 3") == "1 3");
  CHECK(first("⍴,[1.5]1 2 3") == "3 1");
  CHECK(first("⍴,[2 3]2 3 4⍴⍳24") == "2 12");
  CHECK(first("⍴,[1 3]2 3 4⍴⍳24") == "INDEX ERROR");
}

TEST_CASE("catenate along the last axis or the one named; scalars extended") {
  CHECK(first("1 2,3") == "1 2 3");
  CHECK(first("'AB','CD'") == "ABCD");
  CHECK(first("⍴1,2") == "2");
  CHECK(apl("(2 2⍴⍳4),5 6") == Lines{"1 2 5", "3 4 6"});
  CHECK(apl("(2 2⍴⍳4),[1]5 6") == Lines{"1 2", "3 4", "5 6"});
  CHECK(apl("(2 3⍴⍳6),0") == Lines{"1 2 3 0", "4 5 6 0"});
  CHECK(apl("(2 2⍴⍳4),5") == Lines{"1 2 5", "3 4 5"});  // the scalar on every row
  CHECK(apl("0,[1]2 3⍴⍳6") == Lines{"0 0 0", "1 2 3", "4 5 6"});
  CHECK(first("⍴(2 2 2⍴1),1") == "2 2 3");
  CHECK(first("'A',5") == "DOMAIN ERROR");
  CHECK(first("(⍳0),'AB'") == "AB");  // an empty argument takes the other's kind
  CHECK(first("(2 2⍴1),1 2 3") == "LENGTH ERROR");
  CHECK(first("(2 2 2⍴1),1 2") == "RANK ERROR");
  CHECK(first("1 2,[3]3 4") == "INDEX ERROR");
}

TEST_CASE("laminate: a fractional axis makes a new axis of length 2") {
  CHECK(apl("1 2,[0.5]3 4") == Lines{"1 2", "3 4"});
  CHECK(apl("1 2,[1.5]3 4") == Lines{"1 3", "2 4"});
  CHECK(apl("'AB',[0.5]'CD'") == Lines{"AB", "CD"});
  CHECK(apl("1 2,[0.5]0") == Lines{"1 2", "0 0"});
  CHECK(first("⍴(2 3⍴1),[2.5]2 3⍴2") == "2 3 2");
  CHECK(first("1 2,[0.5]1 2 3") == "LENGTH ERROR");
  Apl a;
  a("⎕IO←0");
  CHECK(a("1 2,[¯0.5]3 4") == Lines{"1 2", "3 4"});
  CHECK(a("1 2,[0.5]3 4") == Lines{"1 3", "2 4"});
}

TEST_CASE("reverse and rotate, along the last axis, the first, or the one named") {
  CHECK(first("⌽1 2 3") == "3 2 1");
  CHECK(first("⌽'ABC'") == "CBA");
  CHECK(apl("⌽2 3⍴⍳6") == Lines{"3 2 1", "6 5 4"});
  CHECK(apl("⊖2 3⍴⍳6") == Lines{"4 5 6", "1 2 3"});
  CHECK(apl("⌽[1]2 3⍴⍳6") == Lines{"4 5 6", "1 2 3"});
  CHECK(first("⌽5") == "5");
  CHECK(first("1⌽1 2 3 4") == "2 3 4 1");
  CHECK(first("¯1⌽1 2 3 4") == "4 1 2 3");
  CHECK(first("5⌽1 2 3 4") == "2 3 4 1");
  CHECK(apl("1 2⌽2 3⍴⍳6") == Lines{"2 3 1", "6 4 5"});
  CHECK(apl("1⊖2 3⍴⍳6") == Lines{"4 5 6", "1 2 3"});
  CHECK(apl("0 1 1⊖2 3⍴⍳6") == Lines{"1 5 6", "4 2 3"});
  CHECK(first("1 2⌽1 2 3") == "RANK ERROR");
  CHECK(first("1 2 3⌽2 3⍴⍳6") == "LENGTH ERROR");
  CHECK(first("1.5⌽1 2") == "DOMAIN ERROR");
  CHECK(first("⍴1⌽⍳0") == "0");
}

TEST_CASE("transpose: axes reversed; A⍉B puts B's axis I at A[I], repeated axes a diagonal") {
  CHECK(apl("⍉2 3⍴⍳6") == Lines{"1 4", "2 5", "3 6"});
  CHECK(first("⍴⍉2 3 4⍴⍳24") == "4 3 2");
  CHECK(first("⍉5") == "5");
  CHECK(first("⍉1 2 3") == "1 2 3");
  CHECK(apl("2 1⍉2 3⍴⍳6") == Lines{"1 4", "2 5", "3 6"});
  CHECK(apl("1 2⍉2 3⍴⍳6") == Lines{"1 2 3", "4 5 6"});
  CHECK(first("1 1⍉3 3⍴⍳9") == "1 5 9");
  CHECK(first("⍴2 1 3⍉2 3 4⍴⍳24") == "3 2 4");
  CHECK(first("(2 1 3⍉2 3 4⍴⍳24)[3;2;4]") == "24");
  CHECK(first("1 3⍉2 3⍴⍳6") == "DOMAIN ERROR");
  CHECK(first("1⍉2 3⍴⍳6") == "LENGTH ERROR");
  Apl a;
  a("⎕IO←0");
  CHECK(a("1 0⍉2 3⍴⍳6") == Lines{"0 3", "1 4", "2 5"});
}

}  // namespace igds::apl::test
