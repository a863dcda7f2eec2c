// Reduction, scan, outer and inner products (APL\360 User's Manual, chapter 4): f/ is defined
// from the right, its identity element reduces an empty axis.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "apl_support.h"

namespace igds::apl::test {

TEST_CASE("reduction from the right, along the last axis or the one named") {
  CHECK(first("+/1 2 3") == "6");
  CHECK(first("-/1 2 3") == "2");  // 1-(2-3)
  CHECK(first("÷/8 4 2") == "4");  // 8÷(4÷2)
  CHECK(first("×/⍳5") == "120");
  CHECK(first("⌈/3 1 4") == "4");
  CHECK(first("⌊/3 1 4") == "1");
  CHECK(first("*/2 3 2") == "512");  // 2*(3*2)
  CHECK(first("∧/1 1 0") == "0");
  CHECK(first("∨/0 0 1") == "1");
  CHECK(first("=/1 1") == "1");
  CHECK(first("≠/1 0 1") == "0");
  CHECK(first("+/2 3⍴⍳6") == "6 15");
  CHECK(first("+⌿2 3⍴⍳6") == "5 7 9");
  CHECK(first("+/[1] 2 3⍴⍳6") == "5 7 9");
  CHECK(first("-⌿3 2⍴1 2 3 4 5 6") == "3 4");  // 1-(3-5), 2-(4-6)
  CHECK(first("+/5") == "5");
  CHECK(first("⍴+/5") == "");
  CHECK(apl("+/[2]2 3 4⍴⍳24") == Lines{"15 18 21 24", "51 54 57 60"});
  CHECK(first("+/[4]2 3 4⍴⍳24") == "INDEX ERROR");
  CHECK(first("+/[1.5]1 2") == "DOMAIN ERROR");
  CHECK(first("=/'AA'") == "1");
  CHECK(first("≠/'AB'") == "1");
  CHECK(first("+/'AB'") == "DOMAIN ERROR");
  CHECK(first("+/,'A'") == "A");  // one item: f is not applied
  Apl a;
  a("⎕IO←0");
  CHECK(a("+/[0]2 3⍴⍳6") == Lines{"3 5 7"});
}

TEST_CASE("reduction of an empty axis: the identity element, or DOMAIN ERROR") {
  CHECK(first("+/⍳0") == "0");
  CHECK(first("-/⍳0") == "0");
  CHECK(first("×/⍳0") == "1");
  CHECK(first("÷/⍳0") == "1");
  CHECK(first("*/⍳0") == "1");
  CHECK(first("!/⍳0") == "1");
  CHECK(first("|/⍳0") == "0");
  CHECK(first("∧/⍳0") == "1");
  CHECK(first("∨/⍳0") == "0");
  CHECK(first("=/⍳0") == "1");
  CHECK(first("≠/⍳0") == "0");
  CHECK(first("</⍳0") == "0");
  CHECK(first("≤/⍳0") == "1");
  CHECK(first("(⌈/⍳0)<¯1E300") == "1");  // the most negative number
  CHECK(first("(⌊/⍳0)>1E300") == "1");
  CHECK(first("⍲/⍳0") == "DOMAIN ERROR");
  CHECK(first("○/⍳0") == "DOMAIN ERROR");
  CHECK(first("⍴+/0 3⍴0") == "0");
  CHECK(first("+⌿0 3⍴0") == "0 0 0");
  CHECK(first("+/3 0⍴0") == "0 0 0");
  CHECK(first("=/''") == "1");
}

TEST_CASE("scan: item i is the reduction of the first i items") {
  CHECK(first("+\\1 2 3 4") == "1 3 6 10");
  CHECK(first("-\\1 2 3 4") == "1 ¯1 2 ¯2");
  CHECK(first("×\\1 2 3 4") == "1 2 6 24");
  CHECK(first("÷\\1 2 3 4") == "1 0.5 1.5 0.375");
  CHECK(first("÷\\1 0 2") == "DOMAIN ERROR");  // 1÷(0÷2) divides by 0
  CHECK(first("⌈\\3 1 4 1 5") == "3 3 4 4 5");
  CHECK(first("∧\\1 1 0 1") == "1 1 0 0");
  CHECK(first("<\\0 1 1 0 1") == "0 1 0 0 0");  // the first 1 only
  CHECK(first("≠\\1 0 1 1") == "1 1 0 1");
  CHECK(first("*\\2 3 2") == "2 8 512");
  CHECK(apl("+\\2 3⍴⍳6") == Lines{"1 3  6", "4 9 15"});
  CHECK(apl("+⍀2 3⍴⍳6") == Lines{"1 2 3", "5 7 9"});
  CHECK(apl("-⍀3 2⍴⍳6") == Lines{" 1  2", "¯2 ¯2", " 3  4"});
  CHECK(first("⍴+\\⍳0") == "0");
  CHECK(first("+\\5") == "5");
  CHECK(first("=\\'AB'") == "DOMAIN ERROR");
}

TEST_CASE("outer product: every item of A with every item of B") {
  CHECK(apl("(⍳3)∘.×⍳3") == Lines{"1 2 3", "2 4 6", "3 6 9"});
  CHECK(apl("1 2∘.+10 20 30") == Lines{"11 21 31", "12 22 32"});
  CHECK(apl("'AB'∘.='ABA'") == Lines{"1 0 1", "0 1 0"});
  CHECK(first("⍴(2 3⍴1)∘.+⍳4") == "2 3 4");
  CHECK(first("⍴(⍳0)∘.×⍳3") == "0 3");
  CHECK(first("3∘.-1 2") == "2 1");
  CHECK(first("1 2∘.÷0 1") == "DOMAIN ERROR");
}

TEST_CASE("inner product: f/ of rows of A g columns of B") {
  CHECK(first("1 2 3+.×4 5 6") == "32");
  CHECK(apl("(2 3⍴⍳6)+.×3 2⍴⍳6") == Lines{"22 28", "49 64"});
  CHECK(first("1 2 3∧.=1 2 3") == "1");
  CHECK(first("(3 3⍴'ABCDEFGHI')∧.='DEF'") == "0 1 0");
  CHECK(apl("(2 2⍴1 2 3 4)⌊.+2 2⍴5 6 7 8") == Lines{"6 7", "8 9"});
  CHECK(first("1 2 3-.×4 5 6") == "12");  // 4-(10-18)
  CHECK(first("2+.×1 2 3") == "12");
  CHECK(first("1 2 3+.×2") == "12");
  CHECK(first("(⍳0)+.×⍳0") == "0");
  CHECK(apl("(2 0⍴0)+.×0 3⍴0") == Lines{"0 0 0", "0 0 0"});
  CHECK(first("⍴(2 3 4⍴1)+.×4 5⍴1") == "2 3 5");
  CHECK(first("1 2+.×3 4 5") == "LENGTH ERROR");
  CHECK(first("'AB'+.×1 2") == "DOMAIN ERROR");
}

TEST_CASE("+.× of large matrices agrees with the definition") {
  // Sizes that leave remainders in every block of the product's loops.
  const std::size_t m = 7, n = 300, p = 290;
  std::mt19937 random(17);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Numbers a(m * n), b(n * p);
  for (auto& x : a) x = uniform(random);
  for (auto& x : b) x = uniform(random);
  Apl session;
  session.session.assign("A", Value::of_numbers({m, n}, std::span<const double>(a)));
  session.session.assign("B", Value::of_numbers({n, p}, std::span<const double>(b)));
  session("C←A+.×B");
  auto c = session.session.variable("C");
  REQUIRE(c);
  REQUIRE(c->shape() == Shape{m, p});
  double worst = 0;
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < p; ++j) {
      double s = 0;
      for (std::size_t k = 0; k < n; ++k) s += a[i * n + k] * b[k * p + j];
      worst = std::max(worst, std::fabs(s - c->numbers()[i * p + j]));
    }
  }
  CHECK(worst < 1e-12);
  // The general inner product (right to left) on the same arrays agrees too.
  session("D←A-.×B");
  auto d = session.session.variable("D");
  double s = 0;
  for (std::size_t k = n; k-- > 0;) s = a[k] * b[k * p] - s;
  CHECK(std::fabs(d->numbers()[0] - s) < 1e-9);
}

}  // namespace igds::apl::test
