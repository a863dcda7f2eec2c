// Output as APL shows it (APL2 Language Reference, "display of arrays", and the Dyalog APL
// reference's examples of the same rules): ⎕PP digits, scaled form, columns aligned on their
// decimal points, planes separated by blank lines; ⍕ monadic and with a specification.
#include "interp/apl/format.h"

#include <doctest/doctest.h>

#include "apl_support.h"

namespace igds::apl::test {

TEST_CASE("numbers: ⎕PP significant digits, high minus, scaled beyond ⎕PP or 5 leading zeros") {
  CHECK(format_number(0, 10) == "0");
  CHECK(format_number(-0.0, 10) == "0");
  CHECK(format_number(100, 10) == "100");
  CHECK(format_number(-2.5, 10) == "¯2.5");
  CHECK(format_number(1.0 / 3, 10) == "0.3333333333");
  CHECK(format_number(2.0 / 3, 10) == "0.6666666667");
  CHECK(format_number(0.1, 10) == "0.1");
  CHECK(format_number(123456789012.0, 10) == "1.23456789E11");
  CHECK(format_number(1e10, 10) == "1E10");
  CHECK(format_number(9999999999.0, 10) == "9999999999");
  CHECK(format_number(1e-6, 10) == "0.000001");
  CHECK(format_number(1e-7, 10) == "1E¯7");
  CHECK(format_number(-1.5e-7, 10) == "¯1.5E¯7");
  // The reference's examples with ⎕PP←3: 123 1234 12345 0.12345 0.00012345 0.00000012345.
  CHECK(format_number(123, 3) == "123");
  CHECK(format_number(1234, 3) == "1.23E3");
  CHECK(format_number(12345, 3) == "1.23E4");
  CHECK(format_number(0.12345, 3) == "0.123");
  CHECK(format_number(0.00012345, 3) == "0.000123");
  CHECK(format_number(0.00000012345, 3) == "1.23E¯7");
  CHECK(format_number(0.99999999999, 10) == "1");
}

TEST_CASE("vectors: each number on its own, one blank between") {
  CHECK(first("0.1 1.0 1.12") == "0.1 1 1.12");
  CHECK(first("÷3 2 6") == "0.3333333333 0.5 0.1666666667");
  CHECK(first("1 1E¯7 ¯2") == "1 1E¯7 ¯2");
  CHECK(first("'ABC'") == "ABC");
  CHECK(first("⍳0") == "");
  CHECK(first("''") == "");
  CHECK(first("'A'") == "A");
}

TEST_CASE("matrices: each column in one format, decimal points aligned") {
  CHECK(apl("1 2 3∘.×6 2 5") == Lines{" 6 2  5", "12 4 10", "18 6 15"});
  CHECK(apl("2 3⍴2 4 6.1 8 10.24 12") == Lines{"2  4     6.1", "8 10.24 12"});
  CHECK(apl("2 2⍴1.5 ¯2 10 0.25") == Lines{" 1.5 ¯2", "10    0.25"});
  // A column with a scaled number is scaled throughout, mantissas padded, E's aligned.
  CHECK(apl("2 1⍴1E¯7 1.5") == Lines{"1.0E¯7", "1.5E0"});
  CHECK(apl("2 2⍴'HANDFIST'") == Lines{"HA", "ND"});
  CHECK(apl("2 4⍴'HANDFIST'") == Lines{"HAND", "FIST"});
  CHECK(apl("0 3⍴0") == Lines{});
  CHECK(apl("2 0⍴0") == Lines{});
}

TEST_CASE("higher ranks: one blank line between planes, one more per outer axis") {
  CHECK(apl("2 2 2⍴⍳8") == Lines{"1 2", "3 4", "", "5 6", "7 8"});
  CHECK(apl("2 2 1 1⍴⍳4") == Lines{"1", "", "2", "", "", "3", "", "4"});
  CHECK(apl("2 1 2⍴'ABCD'") == Lines{"AB", "", "CD"});
  // Columns are formatted across all the planes.
  CHECK(apl("2 1 2⍴1 2 30 4") == Lines{" 1 2", "", "30 4"});
}

TEST_CASE("⎕PP and )DIGITS set the digits displayed") {
  Apl a;
  a("⎕PP←3");
  CHECK(a("÷3") == Lines{"0.333"});
  CHECK(a("⎕PP") == Lines{"3"});
  CHECK(a(")DIGITS 5") == Lines{"WAS 3"});
  CHECK(a("○1") == Lines{"3.1416"});
  CHECK(a(")DIGITS") == Lines{"IS 5"});
  CHECK(a(")DIGITS 0") == Lines{"INCORRECT COMMAND"});
  CHECK(a("⎕PP←0")[0] == "DOMAIN ERROR");
  CHECK(a("⎕PP←18")[0] == "DOMAIN ERROR");
  CHECK(a.session.print_precision() == 5);
}

TEST_CASE("⍕ monadic: the characters of the display") {
  CHECK(first("⍴⍕123") == "3");
  CHECK(first("⍴⍕1 2 3") == "5");
  CHECK(first("⍕¯2.5") == "¯2.5");
  CHECK(first("⍴⍕2 2⍴1 2.5 ¯3 400") == "2 8");
  CHECK(apl("⍕2 2⍴1 2.5 ¯3 400") == Lines{" 1   2.5", "¯3 400  "});
  CHECK(first("⍕'ABC'") == "ABC");
  CHECK(first("⍴⍕⍳0") == "0");
  CHECK(first("⍴⍕2 3 4⍴⍳24") == "2 3 11");
  CHECK(first("⍴⍕0 3⍴0") == "0 0");
  CHECK(first("⍴⍕2 0⍴0") == "2 0");
}

TEST_CASE("⍕ dyadic: width and precision per column") {
  CHECK(first("10 2⍕13.87654 6 87.213") == "     13.88      6.00     87.21");
  CHECK(first("5 0⍕3.7") == "    4");
  CHECK(first("0 2⍕22.1987 999.1") == " 22.20 999.10");
  CHECK(first("⍴0 2⍕11.7") == "6");
  CHECK(first("2⍕3.14159") == " 3.14");
  CHECK(first("8 ¯2⍕7.1") == "   7.1E0");
  CHECK(first("10 ¯3⍕¯0.000123") == "  ¯1.23E¯4");
  CHECK(first("6 1⍕¯2.26 0") == "  ¯2.3   0.0");
  CHECK(first("3 1⍕123.4") == "***");
  CHECK(apl("6 2 5 1⍕2 2⍴1.234 5.678 9 10") == Lines{"  1.23  5.7", "  9.00 10.0"});
  CHECK(first("6 2 5⍕1 2") == "LENGTH ERROR");
  CHECK(first("5 1⍕'A'") == "DOMAIN ERROR");
  CHECK(first("¯5 1⍕1") == "DOMAIN ERROR");
}

}  // namespace igds::apl::test
