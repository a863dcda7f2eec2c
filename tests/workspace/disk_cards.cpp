// WRITE: the IGDSCHAR card images of docs/disk.md, byte for byte.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "tests/support/process.h"
#include "tests/support/skip.h"
#include "tests/workspace/disk_fixtures.h"
#include "workspace/disk/cards.h"
#include "workspace/disk/disk.h"
#include "workspace/disk/files.h"
#include "workspace/error.h"
#include "workspace/numbers/fortran.h"

using namespace igds;

namespace {

// A value in WRITE's F10.3, and whether it fits.
std::string f(double v, bool* fits = nullptr) {
  char field[10];
  const bool written = fortran::put_f(field, v, 10, 3);
  if (fits) *fits = written;
  return std::string(field, 10);
}

std::string i5(long long v) {
  char field[5];
  fortran::put_i(field, v, 5);
  return std::string(field, 5);
}

Array array_of(std::vector<std::size_t> shape, Ravel values) {
  Array a(std::move(shape));
  REQUIRE(a.ravel.size() == values.size());
  a.ravel = std::move(values);
  return a;
}

// 2 curves, 2 stringers, INTCU 1, INTST 0; values chosen to show FORTRAN's rounding.
Workspace small_surface() {
  Workspace ws;
  ws.status = {1, 2, 0, 0, 0, 0, 0, 0, 0, 0};
  ws.nocur = 2;
  ws.nostr = 2;
  ws.intcu = 1;
  ws.intst = 0;
  ws.inppn = array_of({4, 3}, {0, 0, 0, 1, 0, 0.5, 0, 1, -0.0005, 1, 1, -0.0004});
  ws.inptg = array_of({8, 4}, {1,       0,           0,          1, 1,       0,      0,       2,
                               1,       0,           0,          3, 1,       0,      0,       4,
                               0,       1,           0,          1, 0.0625,  0.1875, -0.0,    3,
                               1234567, -99999.9996, 999999.999, 2, 0.00025, 1e-310, -1.0005, 4});
  ws.intpn = Array({3, 2, 3});
  for (std::size_t i = 0; i < 18; ++i) ws.intpn.ravel[i] = 0.25 * static_cast<double>(i) - 2;
  ws.patches = Array({1, 1, 3, 4, 4});
  for (std::size_t i = 0; i < 48; ++i) ws.patches.ravel[i] = static_cast<double>(i);
  return ws;
}

// Checked by hand against (10I5) (4I5) (2I5) (8F10.3) ... : every field right-aligned, 8
// numbers a card, the last card of an array short, LF at the end of every card.
const char* const small_surface_cards =
    "    1    2    0    0    0    0    0    0    0    0\n"
    "    2    2    1    0\n"
    "    4    3\n"
    "     0.000     0.000     0.000     1.000     0.000     0.500     0.000     1.000\n"
    "    -0.001     1.000     1.000    -0.000\n"
    "    8    4\n"
    "     1.000     0.000     0.000     1.000     1.000     0.000     0.000     2.000\n"
    "     1.000     0.000     0.000     3.000     1.000     0.000     0.000     4.000\n"
    "     0.000     1.000     0.000     1.000     0.062     0.188    -0.000     3.000\n"
    "********************999999.999     2.000     0.000     0.000    -1.000     4.000\n"
    "    3    2    3\n"
    "    -2.000    -1.750    -1.500    -1.250    -1.000    -0.750    -0.500    -0.250\n"
    "     0.000     0.250     0.500     0.750     1.000     1.250     1.500     1.750\n"
    "     2.000     2.250\n"
    "    1    1    3    4    4\n"
    "     0.000     1.000     2.000     3.000     4.000     5.000     6.000     7.000\n"
    "     8.000     9.000    10.000    11.000    12.000    13.000    14.000    15.000\n"
    "    16.000    17.000    18.000    19.000    20.000    21.000    22.000    23.000\n"
    "    24.000    25.000    26.000    27.000    28.000    29.000    30.000    31.000\n"
    "    32.000    33.000    34.000    35.000    36.000    37.000    38.000    39.000\n"
    "    40.000    41.000    42.000    43.000    44.000    45.000    46.000    47.000\n";

}  // namespace

TEST_CASE("F10.3 as FORTRAN writes it") {
  CHECK(f(0) == "     0.000");
  CHECK(f(1.5) == "     1.500");
  CHECK(f(-0.0005) == "    -0.001");  // the double is a little more than 0.0005 in magnitude
  CHECK(f(-0.0004) == "    -0.000");  // negative values rounding to zero keep their sign
  CHECK(f(-0.0) == "    -0.000");
  CHECK(f(0.0625) == "     0.062");  // an exact half: to even
  CHECK(f(0.1875) == "     0.188");
  CHECK(f(-1.0005) == "    -1.000");  // the double is just under 1.0005
  CHECK(f(std::numeric_limits<double>::denorm_min()) == "     0.000");
  CHECK(f(999999.999) == "999999.999");
  CHECK(f(-99999.999) == "-99999.999");
  CHECK(f(std::nan("")) == "       NaN");
  CHECK(f(INFINITY) == "  Infinity");
  CHECK(f(-INFINITY) == " -Infinity");
  for (double big : {999999.9996, 1e6, -99999.9996, -1e5, 1e300, -1e300}) {
    bool fits = true;
    CHECK(f(big, &fits) == "**********");
    CHECK(!fits);
  }
  CHECK(i5(12) == "   12");
  CHECK(i5(-1234) == "-1234");
  CHECK(i5(123456) == "*****");
  CHECK(i5(-12345) == "*****");
}

TEST_CASE("WRITE: the card images of a small surface, checked by hand") {
  test::TempDir dir;
  Disk disk(dir.path());
  CHECK(write_char(disk, "SMALL", small_surface()) == 2);
  CHECK(test::read_file(disk.path("SMALL", "IGDSCHAR")) == small_surface_cards);
  // Replaced whole by the next WRITE of that name.
  Workspace ws = small_surface();
  ws.inptg.ravel[24] = 1;
  ws.inptg.ravel[25] = 2;
  CHECK(write_char(disk, "SMALL", ws) == 0);
  std::string text = test::read_file(disk.path("SMALL", "IGDSCHAR"));
  CHECK(text.find("     1.000     2.000999999.999") != std::string::npos);
  CHECK(text.size() == std::string(small_surface_cards).size());
}

TEST_CASE("WRITE of a surface not interpolated yet: zero shape cards and no value cards") {
  Workspace ws = small_surface();
  ws.intpn = Array{};
  ws.patches = Array{};
  std::size_t overflow = 0;
  std::string text = disk::char_cards(ws, &overflow);
  CHECK(text.ends_with("    0    0    0\n    0    0    0    0    0\n"));
}

TEST_CASE("WRITE's cards of arrays large enough for every core are the cards one by one") {
  Workspace ws = small_surface();
  // INTPN of 480,000 values: 60,000 cards, made by put_each on all cores. Values of every size
  // and sign, a few too large for F10.3.
  ws.intpn = Array({400, 400, 3});
  for (std::size_t i = 0; i < ws.intpn.size(); ++i)
    ws.intpn.ravel[i] = std::ldexp(static_cast<double>(i % 977) - 488.5, int(i % 23) - 2);
  ws.intpn.ravel[ws.intpn.size() - 1] = 1;  // the last card of fewer than eight values
  std::size_t overflow = 0;
  const std::string text = disk::char_cards(ws, &overflow);
  // The same cards written one by one: the head, then each array's shape and values.
  std::string cards = std::string(small_surface_cards).substr(0, 51 + 21);  // (10I5), (4I5)
  std::size_t asterisks = 0;
  for (const auto& [a, rank] :
       {std::pair{&ws.inppn, 2}, {&ws.inptg, 2}, {&ws.intpn, 3}, {&ws.patches, 5}}) {
    for (int k = 0; k < rank; ++k) cards += i5(static_cast<long long>(a->shape[std::size_t(k)]));
    cards += '\n';
    for (std::size_t k = 0; k < a->size(); ++k) {
      bool fits = true;
      cards += f(a->ravel[k], &fits);
      asterisks += fits ? 0 : 1;
      if (k % 8 == 7 || k + 1 == a->size()) cards += '\n';
    }
  }
  CHECK(asterisks > 1000);
  CHECK(overflow == asterisks);
  CHECK(text.size() == cards.size());
  CHECK(text == cards);
}

TEST_CASE("WRITE on a disk that fills up, in the first piece or a later one: old file kept") {
  test::TempDir dir;
  Disk disk(dir.path());
  Workspace small = small_surface();
  write_char(disk, "SMALL", small);
  const std::string old = test::read_file(disk.path("SMALL", "IGDSCHAR"));
  // More than one piece of cards (8 MB each): about 14 MB.
  Workspace big = test::make_workspace(60, 60, 10, 10, false);
  std::size_t overflow = 0;
  REQUIRE(disk::char_cards(big, &overflow).size() > (std::size_t{9} << 20));
  for (std::size_t limit : {std::size_t{0}, std::size_t{4096}, std::size_t{9} << 20}) {
    CAPTURE(limit);
    disk::set_write_limit_for_testing(limit);
    std::string report;
    try {
      write_char(disk, "SMALL", big);
    } catch (const Report& r) {
      report = r.what();
    }
    disk::set_write_limit_for_testing(std::nullopt);
    CHECK(report == "CANNOT WRITE SMALL.IGDSCHAR (NO SPACE LEFT ON DEVICE); NO FILE CHANGED");
    CHECK(test::read_file(disk.path("SMALL", "IGDSCHAR")) == old);
    CHECK(!std::filesystem::exists(disk::temporary_for(disk.path("SMALL", "IGDSCHAR"))));
  }
  const std::string cards = disk::char_cards(big, &overflow);
  CHECK(write_char(disk, "SMALL", big) == overflow);
  CHECK(test::read_file(disk.path("SMALL", "IGDSCHAR")) == cards);
}

TEST_CASE("WRITE agrees with gfortran writing the same values with the same formats") {
  IGDS_SKIP_UNLESS(test::have_program("gfortran"), "gfortran is not installed");
  test::TempDir dir;
  Workspace ws = test::make_workspace(3, 4, 2, 1, false);
  ws.inppn.ravel[0] = -0.0005;
  ws.inppn.ravel[1] = 0.0625;
  ws.inppn.ravel[2] = 1234567;
  std::string prog = "program cards\n  implicit none\n  integer :: st(10)\n";
  auto put_array = [&](const char* var, const Array& a) {
    prog += fmt::format("  integer(8) :: {}({})\n", var, a.size());
  };
  put_array("b1", ws.inppn);
  put_array("b2", ws.inptg);
  put_array("b3", ws.intpn);
  put_array("b4", ws.patches);
  prog += "  real(8), allocatable :: v(:)\n";
  auto data = [&](const char* var, const Array& a) {
    for (std::size_t i = 0; i < a.size(); ++i)
      prog += fmt::format("  {}({}) = {}_8\n", var, i + 1,
                          std::bit_cast<std::int64_t>(a.ravel[i]) == INT64_MIN
                              ? std::string("-9223372036854775807_8 - 1")
                              : std::to_string(std::bit_cast<std::int64_t>(a.ravel[i])));
  };
  data("b1", ws.inppn);
  data("b2", ws.inptg);
  data("b3", ws.intpn);
  data("b4", ws.patches);
  prog += fmt::format("  st = [{}]\n", fmt::join(ws.status, ", "));
  prog += "  open(10, file='OUT', status='replace')\n";
  prog += "  write(10, '(10I5)') st\n";
  prog +=
      fmt::format("  write(10, '(4I5)') {}, {}, {}, {}\n", ws.nocur, ws.nostr, ws.intcu, ws.intst);
  auto out = [&](const char* var, const Array& a, int rank) {
    prog += fmt::format("  write(10, '({}I5)') {}\n", rank, fmt::join(a.shape, ", "));
    prog +=
        fmt::format("  v = transfer({}, 1.0_8, {})\n  write(10, '(8F10.3)') v\n", var, a.size());
  };
  out("b1", ws.inppn, 2);
  out("b2", ws.inptg, 2);
  out("b3", ws.intpn, 3);
  out("b4", ws.patches, 5);
  prog += "  close(10)\nend program cards\n";
  test::write_file(dir.path() / "cards.f90", prog);
  auto built = test::run({"gfortran", "-ffree-line-length-none", "-o",
                          (dir.path() / "cards").string(), (dir.path() / "cards.f90").string()});
  REQUIRE_MESSAGE(built.status == 0, built.err);
  test::RunOptions in_dir;
  in_dir.cwd = dir.path();
  auto ran = test::run({(dir.path() / "cards").string()}, in_dir);
  REQUIRE(ran.status == 0);
  std::size_t overflow = 0;
  std::string ours = disk::char_cards(ws, &overflow);
  CHECK(ours == test::read_file(dir.path() / "OUT"));
  CHECK(overflow > 0);  // make_workspace puts 1e300 in every array
}
