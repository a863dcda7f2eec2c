// The scalar functions, from their definitions in the APL\360 User's Manual (chapter 2) and the
// APL2 Language Reference, with scalar extension and their domains.
#include <doctest/doctest.h>

#include "apl_support.h"

namespace igds::apl::test {

TEST_CASE("arithmetic: + - × ÷, monadic and dyadic") {
  CHECK(first("5-3") == "2");
  CHECK(first("-3 ¯4") == "¯3 4");
  CHECK(first("+¯2.5") == "¯2.5");
  CHECK(first("×¯2 0 5") == "¯1 0 1");
  CHECK(first("÷4") == "0.25");
  CHECK(first("6÷4") == "1.5");
  CHECK(first("0÷0") == "1");  // APL\360: 0÷0 is 1
  CHECK(first("1÷0") == "DOMAIN ERROR");
  CHECK(first("÷0") == "DOMAIN ERROR");
  CHECK(first("2×3.5") == "7");
}

TEST_CASE("ceiling and floor, maximum and minimum") {
  CHECK(first("⌈2.5 ¯2.5 3") == "3 ¯2 3");
  CHECK(first("⌊2.5 ¯2.5 3") == "2 ¯3 3");
  CHECK(first("3⌈5 1") == "5 3");
  CHECK(first("3⌊5 1") == "3 1");
  // Tolerant: a number within ⎕CT of an integer is that integer.
  CHECK(first("⌊1-1E¯15") == "1");
  CHECK(first("⌈1+1E¯15") == "1");
}

TEST_CASE("power, exponential, logarithms") {
  CHECK(first("2*3 0 ¯1") == "8 1 0.5");
  CHECK(first("*0 1") == "1 2.718281828");
  CHECK(first("4*0.5") == "2");
  CHECK(first("0*0") == "1");
  CHECK(first("0*¯1") == "DOMAIN ERROR");
  CHECK(first("¯8*÷3") == "DOMAIN ERROR");  // no complex numbers
  CHECK(first("¯2*3") == "¯8");
  CHECK(first("⍟1") == "0");
  CHECK(first("10⍟1000") == "3");
  CHECK(first("2⍟8") == "3");
  CHECK(first("⍟0") == "DOMAIN ERROR");
  CHECK(first("⍟¯1") == "DOMAIN ERROR");
  CHECK(first("10*400") == "DOMAIN ERROR");  // overflow: no infinity in APL
  CHECK(first("1E308×10") == "DOMAIN ERROR");
}

TEST_CASE("magnitude and residue: the sign of the left argument") {
  CHECK(first("|¯3 2") == "3 2");
  CHECK(first("3|7") == "1");
  CHECK(first("3|¯7") == "2");
  CHECK(first("¯3|7") == "¯2");
  CHECK(first("0|5") == "5");
  CHECK(first("2|¯1.5") == "0.5");
  CHECK(first("0.1|1") == "0");  // 1÷0.1 is tolerantly an integer
  CHECK(first("1|2.25") == "0.25");
}

TEST_CASE("factorial is the gamma function; binomial coefficients") {
  CHECK(first("!0 1 5") == "1 1 120");
  CHECK(first("!0.5") == "0.8862269255");  // Γ(1.5) = √π÷2
  CHECK(first("!¯1") == "DOMAIN ERROR");
  CHECK(first("!¯0.5") == "1.772453851");  // Γ(0.5) = √π
  CHECK(first("2!5") == "10");
  CHECK(first("5!2") == "0");
  CHECK(first("0!0") == "1");
  CHECK(first("¯1!3") == "0");
  CHECK(first("2!¯3") == "6");             // (¯3×¯4)÷2
  CHECK(first("3!¯2") == "¯4");            // (¯2×¯3×¯4)÷6
  CHECK(first("¯3!¯1") == "1");            // 0 ≤ B-A: (¯1*B-A)×(B-A)!(-A+1)
  CHECK(first("0.5!1") == "1.273239545");  // Γ(2)÷Γ(1.5)×Γ(1.5) = 4÷π
}

TEST_CASE("pi times and the circular functions") {
  CHECK(first("○1") == "3.141592654");
  CHECK(first("1○0") == "0");
  CHECK(first("2○0") == "1");
  CHECK(first("2○○1") == "¯1");
  CHECK(first("0○0.6") == "0.8");
  CHECK(first("4○0.75") == "1.25");
  CHECK(first("¯4○1.25") == "0.75");
  CHECK(first("¯1○1") == "1.570796327");
  CHECK(first("¯3○1") == "0.7853981634");
  CHECK(first("7○0") == "0");
  CHECK(first("¯1○2") == "DOMAIN ERROR");
  CHECK(first("8○1") == "DOMAIN ERROR");
  CHECK(first("1.5○1") == "DOMAIN ERROR");
}

TEST_CASE("roll: ⎕IO to B-1+⎕IO, repeatable from ⎕RL") {
  Apl a;
  a("⎕RL←12345");
  const Lines once = a("?10 10 10 10 10 10");
  a("⎕RL←12345");
  CHECK(a("?10 10 10 10 10 10") == once);
  a("⎕RL←12345");
  CHECK(a("∧/(R≥1)∧(R≤10)∧R=⌊R←?100⍴10") == Lines{"1"});
  a("⎕IO←0");
  CHECK(a("∧/(R≥0)∧(R≤9)∧R=⌊R←?100⍴10") == Lines{"1"});
  CHECK(first("?0") == "DOMAIN ERROR");
  CHECK(first("?2.5") == "DOMAIN ERROR");
}

TEST_CASE("relations, with the comparison tolerance; characters with = and ≠ only") {
  CHECK(first("3<5 3 1") == "1 0 0");
  CHECK(first("3≤5 3 1") == "1 1 0");
  CHECK(first("1 2 3=1 5 3") == "1 0 1");
  CHECK(first("3≥5 3 1") == "0 1 1");
  CHECK(first("3>5 3 1") == "0 0 1");
  CHECK(first("3≠5 3 1") == "1 0 1");
  CHECK(first("1=1+1E¯14") == "1");
  CHECK(first("1=1+1E¯10") == "0");
  CHECK(first("1<1+1E¯14") == "0");
  CHECK(first("'A'='A'") == "1");
  CHECK(first("3='A3'") == "0 0");
  CHECK(first("'AB'≠'AC'") == "0 1");
  CHECK(first("'A'<'B'") == "DOMAIN ERROR");
  CHECK(first("'A'+1") == "DOMAIN ERROR");
  CHECK(first("-'A'") == "DOMAIN ERROR");
}

TEST_CASE("logic on 0 and 1 only") {
  CHECK(first("0 0 1 1∧0 1 0 1") == "0 0 0 1");
  CHECK(first("0 0 1 1∨0 1 0 1") == "0 1 1 1");
  CHECK(first("0 0 1 1⍲0 1 0 1") == "1 1 1 0");
  CHECK(first("0 0 1 1⍱0 1 0 1") == "1 0 0 0");
  CHECK(first("~1 0") == "0 1");
  CHECK(first("2∧1") == "DOMAIN ERROR");
  CHECK(first("~2") == "DOMAIN ERROR");
  CHECK(first("1^1") == "1");  // ^ is read as ∧
}

TEST_CASE("scalar extension: a scalar or a one-element array goes with anything") {
  CHECK(first("1+1 2 3") == "2 3 4");
  CHECK(first("1 2 3+1") == "2 3 4");
  CHECK(first("(,5)+1 2") == "6 7");
  CHECK(apl("10×2 2⍴⍳4") == Lines{"10 20", "30 40"});
  CHECK(apl("(1 1⍴5)+2 2⍴⍳4") == Lines{"6 7", "8 9"});
  CHECK(first("⍴(1 1⍴5)+,3") == "1 1");
  CHECK(first("1 2+1 2 3") == "LENGTH ERROR");
  CHECK(first("(2 2⍴1)+1 2") == "RANK ERROR");
  CHECK(first("(2 2⍴1)+2 3⍴1") == "LENGTH ERROR");
  CHECK(first("⍴(⍳0)+⍳0") == "0");
  CHECK(first("⍴1+⍳0") == "0");
}

}  // namespace igds::apl::test
