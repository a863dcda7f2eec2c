// DUCT 4.4 picture files (workspace/exchange/duct.h): a picture written by hand from
// docs/exchange.md ("The file"), read and drawn item by item; the tolerant reader; damaged
// pictures refused with their line and reason; conic arcs; the writer's fields; round trips; the
// golden pictures of a surface.
#include "workspace/exchange/duct.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "tests/support/skip.h"
#include "tests/workspace/exchange_support.h"
#include "workspace/drawing/project.h"
#include "workspace/exchange/dates.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/data_error.h"
#include "workspace/numbers/fortran.h"
#include "workspace/text_out.h"

namespace igds::test::exchange {

namespace {

std::string hand_written() {
  return read_file(source_dir() / "tests/workspace/data/hand_written.ductpic");
}

Vec3 point_of(const Drawing3& d, const Drawing3::Item& item, std::size_t k) {
  return d.points(item)[k];
}

bool near(Vec3 a, Vec3 b, double tolerance) {
  return norm(a - b) <= tolerance;
}

// A drawing's picture as EXPORT DUCT writes it, straight from the drawing; it must be the text of
// the picture kept whole.
template <class... Args>
std::string streamed(const Args&... args) {
  StringOut out;
  write_duct(args..., out);
  return out.take_text();
}

// A point of a rational quadratic span by de Casteljau in homogeneous coordinates.
Vec3 conic_point(const Vec3 c[3], const double w[3], double t) {
  const double s = 1 - t;
  const double b0 = s * s * w[0], b1 = 2 * s * t * w[1], b2 = t * t * w[2];
  return (1 / (b0 + b1 + b2)) * (b0 * c[0] + b1 * c[1] + b2 * c[2]);
}

// Every span of a degree-2 curve item sampled: the largest distance from `centre` minus `radius`.
double off_circle(const Drawing3& d, const Drawing3::Item& item, Vec3 centre, double radius) {
  const auto p = d.points(item);
  const auto w = d.weights(item);
  double worst = 0;
  for (std::size_t k = 0; k + 2 < p.size(); k += 2) {
    const Vec3 c[3] = {p[k], p[k + 1], p[k + 2]};
    const double ws[3] = {w[k], w[k + 1], w[k + 2]};
    for (int i = 0; i <= 64; ++i)
      worst = std::max(worst, std::abs(norm(conic_point(c, ws, i / 64.0) - centre) - radius));
  }
  return worst;
}

// The error a picture refuses with (or none).
std::optional<DuctError> refusal(const std::string& text) {
  try {
    read_duct(text);
  } catch (const DuctError& e) {
    return e;
  }
  return std::nullopt;
}

// A small good picture (line numbers in the damaged tests refer to it): two instructions, a
// straight line and Bézier spans continuing it, five pixels.
const std::string small_picture =
    "SMALL 01 JAN 1975 00:00:00\n"                                              // 1
    " *\n"                                                                      // 2
    "      4     3    -1     2     5     0     3     0     0     0\n"           // 3
    "    0.0000   10.0000    0.0000   10.0000    0.0000    0.0000    0.0000\n"  // 4
    "        2048      2\n"                                                     // 5
    "        3096      3\n"                                                     // 6
    "  0.0000000E+00  0.0000000E+00  0.0000000E+00\n"                           // 7
    "  0.1000000E+02  0.0000000E+00  0.0000000E+00\n"                           // 8
    "  0.1000000E+02  0.5000000E+01  0.0000000E+00\n"                           // 9
    "  0.5000000E+01  0.1000000E+02  0.0000000E+00\n"                           // 10
    "  0.0000000E+00  0.1000000E+02  0.0000000E+00\n";                          // 11

// `text` with line `number` (1-based) replaced by `line` (removed when nullopt).
std::string with_line(const std::string& text, std::size_t number,
                      std::optional<std::string> line) {
  std::istringstream in(text);
  std::string out, l;
  for (std::size_t n = 1; std::getline(in, l); ++n) {
    if (n == number) {
      if (line) out += *line + "\n";
    } else {
      out += l + "\n";
    }
  }
  return out;
}

void expect_refusal(const std::string& text, DuctError::Problem problem, std::size_t line) {
  const auto e = refusal(text);
  REQUIRE(e);
  CAPTURE(e->what());
  CHECK(e->problem == problem);
  CHECK(e->line == line);
  CHECK(e->reason().rfind("LINE " + std::to_string(line) + ": ", 0) == 0);
}

// A picture read as DUCT's FORTRAN READs read it: every record in the columns of its format
// (docs/exchange.md, "The file") through fortran::read_i and read_f, nothing past them, column 1
// blank. Fails the test at the first record that is not so.
DuctPicture read_columns(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::size_t number = 0;
  auto next = [&] {
    REQUIRE(std::getline(in, line));
    ++number;
    return std::string_view(line);
  };
  // The fields of a record: widths, each an integer or a real with `decimals`.
  struct Field {
    std::size_t width;
    int decimals;  // -1: an integer
  };
  auto record = [&](std::string_view card, const std::vector<Field>& fields,
                    std::size_t skip_before_each, std::vector<double>& out) {
    CAPTURE(number);
    CAPTURE(card);
    std::size_t at = 0;
    for (const Field& f : fields) {
      if (skip_before_each > 0 || at == 0) {
        const std::size_t blank = at == 0 ? 1 : skip_before_each;
        for (std::size_t k = at; k < at + blank && k < card.size(); ++k) REQUIRE(card[k] == ' ');
        at += blank;
      }
      if (f.decimals < 0) {
        const auto v = fortran::read_i(card, at, f.width);
        REQUIRE(v);
        out.push_back(double(*v));
      } else {
        const auto v = fortran::read_f(card, at, f.width, f.decimals);
        REQUIRE(v);
        out.push_back(*v);
      }
      at += f.width;
    }
    REQUIRE(card.size() <= at);
  };
  DuctPicture p;
  while (next() != " *") p.header.push_back(line);
  std::vector<double> v;
  record(next(), std::vector<Field>(10, {6, -1}), 0, v);
  for (std::size_t k = 0; k < 10; ++k) p.counters[k] = std::int64_t(v[k]);
  v.clear();
  record(next(), std::vector<Field>(7, {10, 4}), 0, v);
  std::copy(v.begin(), v.end(), p.reals.begin());
  for (std::int64_t k = 0; k < p.counters[3]; ++k) {
    v.clear();
    record(next(), {{11, -1}, {6, -1}}, 1, v);
    auto in = decompose_duct_code(std::int64_t(v[0]));
    REQUIRE(in);
    in->pixels = std::size_t(v[1]);
    p.instructions.push_back(*in);
  }
  const bool tu = p.counters[0] % 2 == 1;
  for (std::int64_t k = 0; k < p.counters[4]; ++k) {
    v.clear();
    std::vector<Field> fields(3, {14, 7});
    if (tu) fields.insert(fields.end(), 2, {10, 4});
    record(next(), fields, 1, v);
    p.xyz.insert(p.xyz.end(), v.begin(), v.begin() + 3);
    if (tu) p.tu.insert(p.tu.end(), v.begin() + 3, v.end());
  }
  if (p.counters[0] / 2 % 2 == 1) {
    v.clear();
    record(next(), {{6, -1}, {6, -1}}, 0, v);
    const std::size_t texts = std::size_t(v[0]), dimensions = std::size_t(v[1]);
    for (std::size_t k = 0; k < texts; ++k) {
      v.clear();
      const std::string card = std::string(next());
      record(std::string_view(card).substr(0, 33),
             {{8, -1}, {3, -1}, {3, -1}, {2, -1}, {8, 3}, {8, 3}}, 0, v);
      DuctText t{std::size_t(v[0]), int(v[2]), int(v[3]), v[4], v[5], {}};
      REQUIRE(card.substr(33, 17) == std::string(17, ' '));
      t.text = card.substr(50);
      if (v[1] > 30) t.text += std::string(next()).substr(1);
      REQUIRE(t.text.size() == std::size_t(v[1]));
      p.texts.push_back(t);
    }
    for (std::size_t k = 0; k < dimensions; ++k) next();
  }
  CHECK(!std::getline(in, line));
  return p;
}

// The items of `d` scaled by `scale` about the origin, then moved by `by`, added to `out`.
void add_moved(Drawing3& out, const Drawing3& d, double scale, Vec3 by) {
  std::vector<double> xyz;
  for (const auto& item : d.items()) {
    xyz.clear();
    for (Vec3 v : d.points(item)) {
      const Vec3 w = scale * v + by;
      xyz.insert(xyz.end(), {w.x, w.y, w.z});
    }
    const Vec3View points(xyz.data(), xyz.size() / 3);
    switch (item.kind) {
      case Drawing3::Kind::polyline:
        out.add_polyline(points, item.style, item.id, item.closed);
        break;
      case Drawing3::Kind::curve:
        out.add_curve(item.degree, points, d.weights(item), item.style, item.id);
        break;
      case Drawing3::Kind::mark:
        out.add_mark(points[0], item.shape, item.size, item.style, item.id);
        break;
      case Drawing3::Kind::text:
        out.add_text(points[0], d.text(item), item.size, item.style, item.id);
        break;
    }
  }
}

// `d` scaled by `scale` about the origin, then moved by `by`.
Drawing3 moved(const Drawing3& d, double scale, Vec3 by) {
  Drawing3 out;
  add_moved(out, d, scale, by);
  return out;
}

}  // namespace

TEST_CASE("instruction codes decompose into their six parts and back") {
  int valid = 0;
  for (std::int64_t code = 0; code < 3 * 2048; ++code) {
    const auto in = decompose_duct_code(code);
    if (!in) continue;
    ++valid;
    CHECK(in->code() == code);
  }
  // Colours 0..2, 3 arc kinds, 5 marks, 2 positions, 4 pen codes, 3 dashes.
  CHECK(valid == 3 * 3 * 5 * 2 * 4 * 3);
  const auto a = decompose_duct_code(4897);  // the DUCT format's example
  REQUIRE(a);
  CHECK(a->colour == 2);
  CHECK(a->arc == DuctArc::conic);
  CHECK(a->mark == DuctMark::diamond);
  CHECK(a->mark_all);
  CHECK(a->pen == DuctPen::move);
  CHECK(a->dash == DuctDash::dashed);
  for (std::int64_t bad : {std::int64_t(2051), std::int64_t(2048 + 1536), std::int64_t(2048 + 320),
                           std::int64_t(-2048), std::int64_t(1) << 31})
    CHECK_FALSE(decompose_duct_code(bad));
}

TEST_CASE("the dates of the exchange files") {
  CHECK(duct_date({1987, 9, 22, 9, 55, 50}) == "22 SEP 1987 09:55:50");
  CHECK(duct_date({1987, 13, 22, 9, 55, 50}) == "22 ??? 1987 09:55:50");
  CHECK(iges_date({1987, 9, 22, 9, 55, 50}) == "19870922.095550");
  CHECK(iso_date({1987, 9, 22, 9, 55, 50}) == "1987-09-22T09:55:50");
}

TEST_CASE("the hand-written picture is read as the format says") {
  const DuctPicture p = read_duct(hand_written());
  REQUIRE(p.header.size() == 2);
  CHECK(p.header[0] == "DUCT MARK 4.4 PICTURE FILE HANDWRITTEN 14 MAR 1988 10:15:00");
  CHECK(p.counters == std::array<std::int64_t, 10>{7, 3, -1, 10, 30, 0, 3, 0, 0, 0});
  CHECK(p.reals == std::array<double, 7>{-2.0711, 50, -5, 35, 0, 5, 0});
  CHECK(p.has_tu());
  CHECK(p.has_texts());
  REQUIRE(p.instructions.size() == 10);
  const std::vector<std::int64_t> codes = {2112, 2072,  4264, 4113, 6946,
                                           2584, 10833, 9440, 3098, 2056};
  const std::vector<std::size_t> pixels = {1, 2, 3, 2, 3, 4, 3, 7, 3, 2};
  for (std::size_t n = 0; n < 10; ++n) {
    CHECK(p.instructions[n].code() == codes[n]);
    CHECK(p.instructions[n].pixels == pixels[n]);
  }
  const DuctInstruction& seventh = p.instructions[6];
  CHECK(seventh.colour == 5);
  CHECK(seventh.arc == DuctArc::conic);
  CHECK(seventh.mark == DuctMark::cross);
  CHECK_FALSE(seventh.mark_all);
  CHECK(seventh.pen == DuctPen::visible);
  CHECK(seventh.dash == DuctDash::dashed);
  REQUIRE(p.pixel_count() == 30);
  CHECK(Vec3::load(&p.xyz[3 * 9]) == Vec3{47.07107, 7.071068, 0});
  CHECK(p.tu[2 * 9] == 1);
  CHECK(p.tu[2 * 13] == -2);
  CHECK(Vec3::load(&p.xyz[3 * 29]) == Vec3{40, -5, 0});
  REQUIRE(p.texts.size() == 3);
  CHECK(p.texts[0] ==
        DuctText{29, 2, 1, 0, 3, "IGDS HAND-WRITTEN DUCT PICTURE FOR THE READER TESTS"});
  CHECK(p.texts[1] == DuctText{1, 1, 2, 45, 2.5, "ORIGIN"});
  CHECK(p.texts[2] == DuctText{30, 1, 0, 0, 3, "%mm"});
  REQUIRE(p.dimensions.size() == 1);
  CHECK(p.dimensions[0].k == std::array<std::int64_t, 11>{1, 1, 0, 1, 2, 0, 30, 1, 1, 2, 0});
  CHECK(p.dimensions[0].t == 0);
}

TEST_CASE("the hand-written picture drawn item by item") {
  const Drawing3 d = duct_drawing(read_duct(hand_written()));
  const auto items = d.items();
  REQUIRE(items.size() == 21);
  using K = Drawing3::Kind;
  auto check_item = [&](std::size_t k, K kind, int pen, Dash dash, int instruction) {
    CAPTURE(k);
    CHECK(items[k].kind == kind);
    CHECK(items[k].style.pen == pen);
    if (kind != K::mark) CHECK(items[k].style.dash == dash);
    CHECK(items[k].id == Identity{Role::line, instruction});
  };
  auto check_mark = [&](std::size_t k, MarkShape shape, Vec3 at) {
    CAPTURE(k);
    CHECK(items[k].shape == shape);
    CHECK(items[k].size == duct_mark_size);
    CHECK(point_of(d, items[k], 0) == at);
  };
  const Vec3 origin{0, 0, 0};
  // 1: 2112, an X on its one pixel; a single pixel draws no line.
  check_item(0, K::mark, 1, Dash::solid, 1);
  check_mark(0, MarkShape::cross, origin);
  // 2: 2072, IUPDN 24: straight lines on from pixel 1.
  check_item(1, K::polyline, 1, Dash::solid, 2);
  REQUIRE(d.points(items[1]).size() == 3);
  CHECK(point_of(d, items[1], 0) == origin);
  CHECK(point_of(d, items[1], 2) == Vec3{10, 10, 0});
  // 3: 4264, invisible, a plus on every pixel, colour 2.
  for (std::size_t k = 2; k <= 4; ++k) check_item(k, K::mark, 2, Dash::solid, 3);
  check_mark(2, MarkShape::plus, {20, 0, 0});
  check_mark(4, MarkShape::plus, {30, 0, 0});
  // 4: 4113, IUPDN 16: a visible line from the last pixel of 3, dashed, colour 2.
  check_item(5, K::polyline, 2, Dash::dashed, 4);
  REQUIRE(d.points(items[5]).size() == 3);
  CHECK(point_of(d, items[5], 0) == Vec3{30, 0, 0});
  CHECK(point_of(d, items[5], 2) == Vec3{40, 10, 0});
  // 5: 6946, a quarter circle (s = 1, M equidistant), chain dashed, colour 3, diamonds at the
  // span's ends.
  check_item(6, K::curve, 3, Dash::chain, 5);
  CHECK(items[6].degree == 2);
  REQUIRE(d.points(items[6]).size() == 3);
  CHECK(near(point_of(d, items[6], 1), {50, 10, 0}, 1e-5));
  CHECK(d.weights(items[6])[1] == doctest::Approx(std::sqrt(0.5)).epsilon(1e-6));
  CHECK(off_circle(d, items[6], {40, 0, 0}, 10) < 1e-5);
  check_item(7, K::mark, 3, Dash::chain, 5);
  check_mark(7, MarkShape::diamond, {50, 0, 0});
  check_mark(8, MarkShape::diamond, {40, 10, 0});
  // 6: 2584, IUPDN 24 conic arcs: a parabola (s = 0: weight 1, control 2M - Q), then s = -2,
  // f < 0, the wrong half of the hyperbola: the two lines P0 M and M P1.
  check_item(9, K::curve, 1, Dash::solid, 6);
  REQUIRE(d.points(items[9]).size() == 7);
  CHECK(point_of(d, items[9], 0) == Vec3{40, 10, 0});
  CHECK(near(point_of(d, items[9], 1), {35, 15, 0}, 1e-12));
  CHECK(point_of(d, items[9], 2) == Vec3{30, 10, 0});
  CHECK(point_of(d, items[9], 3) == Vec3{27.5, 12.5, 0});
  CHECK(point_of(d, items[9], 4) == Vec3{25, 15, 0});
  CHECK(point_of(d, items[9], 5) == Vec3{22.5, 12.5, 0});
  CHECK(point_of(d, items[9], 6) == Vec3{20, 10, 0});
  for (double w : d.weights(items[9])) CHECK(w == 1);
  // 7: 10833, IUPDN 16: a visible straight join, then three quarters of a circle (s = 1,
  // f > 2: two spans), an X on the first pixel only, dashed, colour 5.
  check_item(10, K::polyline, 5, Dash::dashed, 7);
  CHECK(point_of(d, items[10], 0) == Vec3{20, 10, 0});
  CHECK(point_of(d, items[10], 1) == Vec3{0, 20, 0});
  check_item(11, K::curve, 5, Dash::dashed, 7);
  REQUIRE(d.points(items[11]).size() == 5);
  for (double w : d.weights(items[11])) CHECK(w > 0);
  CHECK(off_circle(d, items[11], {5, 25, 0}, 5 * std::sqrt(2.0)) < 1e-5);
  CHECK(near(point_of(d, items[11], 2), {5, 32.07107, 0}, 1e-12));
  check_item(12, K::mark, 5, Dash::dashed, 7);
  check_mark(12, MarkShape::cross, {0, 20, 0});
  // 8: 9440, two Bézier spans, squares at the span ends (not the controls), colour 4.
  check_item(13, K::curve, 4, Dash::solid, 8);
  CHECK(items[13].degree == 3);
  CHECK(d.weights(items[13]).empty());
  REQUIRE(d.points(items[13]).size() == 7);
  check_mark(14, MarkShape::square, {0, 30, 0});
  check_mark(15, MarkShape::square, {10, 30, 0});
  check_mark(16, MarkShape::square, {20, 30, 5});
  // 9: 3098, IUPDN 24 Bézier span from pixel 25, chain dashed.
  check_item(17, K::curve, 1, Dash::chain, 9);
  REQUIRE(d.points(items[17]).size() == 4);
  CHECK(point_of(d, items[17], 0) == Vec3{20, 30, 5});
  CHECK(point_of(d, items[17], 3) == Vec3{30, 30, 5});
  // 10: 2056, invisible and unmarked: nothing. The texts, at their pixels.
  CHECK(items[18].kind == K::text);
  CHECK(d.text(items[18]) == "IGDS HAND-WRITTEN DUCT PICTURE FOR THE READER TESTS");
  CHECK(point_of(d, items[18], 0) == Vec3{0, -5, 0});
  CHECK(items[18].style.pen == 2);
  CHECK(items[18].id == Identity{Role::label, 1, 29});
  CHECK(d.text(items[19]) == "ORIGIN");
  CHECK(point_of(d, items[19], 0) == origin);
  CHECK(d.text(items[20]) == "%mm");
  CHECK(point_of(d, items[20], 0) == Vec3{40, -5, 0});
}

TEST_CASE("the reader is tolerant as list-directed FORTRAN reads are") {
  const DuctPicture original = read_duct(hand_written());
  // The numbers of the hand-written picture re-laid: separated by commas, tabs or single blanks,
  // the counters on two lines, D exponents, a blank line between the sections, CR LF ends.
  std::istringstream in(hand_written());
  std::string line, text;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (n >= 4 && n <= 45) {
      std::istringstream tokens(line);
      std::vector<std::string> t;
      for (std::string w; tokens >> w;) t.push_back(w);
      for (auto& w : t)
        if (n % 3 == 0) std::replace(w.begin(), w.end(), 'E', 'D');
      std::string joined;
      for (std::size_t k = 0; k < t.size(); ++k) {
        if (n == 4 && k == 4)
          joined += "\r\n";
        else if (k > 0)
          joined += n % 2 == 0 ? "," : (n % 5 == 0 ? "\t" : " ");
        joined += t[k];
      }
      line = joined;
    }
    text += line + "\r\n";
    if (n == 15) text += "   \r\n";
  }
  const DuctPicture relaid = read_duct(text);
  CHECK(relaid == original);

  // Fields packed in their columns: -12345 fills its I6, 12345.6789 its F10.4.
  const std::string packed =
      "PACKED\n *\n      4     3    -1     1     1     0     3-12345-12345-12345\n"
      " -1234.5678 1234.5678-1234.5678-1234.5678-1234.5678-1234.5678-1234.5678\n"
      "        2056      1\n  0.1000000E+01  0.2000000E+01  0.3000000E+01\n";
  const DuctPicture p = read_duct(packed);
  CHECK(p.counters[9] == -12345);
  CHECK(p.reals[0] == -1234.5678);
  CHECK(p.reals[1] == 1234.5678);
  // A header of one line; trailing blank lines; the '*' anywhere on its line.
  CHECK_NOTHROW(
      read_duct("X\n   *  \n" + with_line(small_picture, 1, std::nullopt).substr(3) + "\n  \n"));
}

TEST_CASE("damaged pictures are refused with the line and the reason") {
  using P = DuctError::Problem;
  REQUIRE_NOTHROW(read_duct(small_picture));
  expect_refusal(with_line(small_picture, 2, std::nullopt), P::no_star, 11);
  expect_refusal("", P::no_star, 1);
  expect_refusal(with_line(small_picture, 11, std::nullopt), P::truncated, 11);
  expect_refusal(small_picture.substr(0, small_picture.find("3096") - 8), P::truncated, 6);
  expect_refusal(with_line(small_picture, 8, "  0.1x00000E+02  0.0000000E+00  0.0000000E+00"),
                 P::not_a_number, 8);
  expect_refusal(with_line(small_picture, 5, "        2048      2.5"), P::not_a_number, 5);
  expect_refusal(with_line(small_picture, 9, "  0.1E+02  0.5E+01  0.0E+00  0.0E+00"),
                 P::too_many_numbers, 9);
  expect_refusal(
      with_line(small_picture, 3, "      3     3    -1     2     5     0     3     0     0     0"),
      P::version, 3);
  auto counter = [&](const char* line, int which) {
    const auto e = refusal(with_line(small_picture, 3, std::string(line)));
    REQUIRE(e);
    CHECK(e->problem == P::counter);
    CHECK(e->which == which);
    CHECK(e->line == 3);
  };
  counter("      4     4    -1     2     5     0     3     0     0     0", 2);
  counter("      4     3    -1     0     5     0     3     0     0     0", 4);
  counter("      4     3    -1     2    -5     0     3     0     0     0", 5);
  counter("      4     3    -1     2     5     0     5     0     0     0", 7);
  expect_refusal(with_line(small_picture, 3,
                           "      4     3    -1     2 5000000     0     3     0     0     0"),
                 P::too_large, 3);
  expect_refusal(with_line(small_picture, 5, "        2051      2"), P::code, 5);
  expect_refusal(with_line(small_picture, 5, "        2048      0"), P::no_pixels, 5);
  // Bézier spans of IUPDN 0 need 3n+1 pixels, conic arcs 2n+1 (2n after IUPDN 24).
  expect_refusal(with_line(small_picture, 6, "        3072      3"), P::arc_pixels, 6);
  expect_refusal(with_line(small_picture, 6, "        2584      3"), P::arc_pixels, 6);
  expect_refusal(with_line(small_picture, 5, "        2072      2"), P::nothing_to_continue, 5);
  expect_refusal(
      with_line(small_picture, 3, "      4     3    -1     2     4     0     3     0     0     0"),
      P::pixel_sum, 6);
  expect_refusal(
      with_line(small_picture, 3, "      4     3    -1     2     6     0     3     0     0     0") +
          "  0.0000000E+00  0.1000000E+02  0.0000000E+00\n",
      P::pixel_sum, 3);
  expect_refusal(
      with_line(small_picture, 3, "      4     3    -1     3     5     0     3     0     0     0") +
          "  0.0000000E+00  0.1000000E+02  0.0000000E+00\n",
      P::instruction_count, 7);
  expect_refusal(
      with_line(small_picture, 3, "      4     3    -1     2     5    -2     3     0     0     0"),
      P::only_lines, 6);
  const std::string with_text =
      with_line(small_picture, 3, "      6     3    -1     2     5     0     3     0     0     0");
  REQUIRE_NOTHROW(read_duct(with_text + "      1     0\n        5  2  1 1   0.000   3.000" +
                            std::string(17, ' ') + "OK\n"));
  expect_refusal(with_text + "      1     0\n        6  2  1 1   0.000   3.000" +
                     std::string(17, ' ') + "NO\n",
                 P::text_pixel, 13);
  expect_refusal(with_text + "      1     0\n        5 81  1 1   0.000   3.000" +
                     std::string(17, ' ') + "NO\n",
                 P::text_length, 13);
  expect_refusal(
      with_text +
          "      0     1\n  1       9       0 1       2       0       1  1  1  2 0   0.000\n",
      P::text_pixel, 13);
  expect_refusal(with_text + "     -1     0\n", P::text_counts, 12);
  expect_refusal(small_picture + " 1 2 3\n", P::trailing, 12);
}

TEST_CASE("refusals come before any allocation for the counts") {
  // Counts of four million pixels in a file of a dozen lines: refused as truncated at once.
  const auto e = refusal(with_line(
      small_picture, 3, "      4     3    -1     1 4000000     0     3     0     0     0"));
  REQUIRE(e);
  CHECK(e->problem == DuctError::Problem::truncated);
  CHECK(e->expected == 4000001 - 7);
}

TEST_CASE("conic arcs: circles, parabolas, hyperbolas, the major arc and the fallback") {
  // A quarter circle from s = 1 with M on the arc's middle stays within 1e-12 of the circle.
  const double r = std::sqrt(0.5);
  ConicSpans q = conic_spans({1, 0, 0}, {r, r, 0}, {0, 1, 0}, 1);
  REQUIRE(q.spans == 1);
  CHECK_FALSE(q.lines);
  CHECK(std::abs(q.weights[1] - r) < 1e-15);
  CHECK(norm(q.controls[1] - Vec3{1, 1, 0}) < 1e-15);
  double worst = 0;
  for (int i = 0; i <= 1000; ++i) {
    const Vec3 c[3] = {q.controls[0], q.controls[1], q.controls[2]};
    const double w[3] = {q.weights[0], q.weights[1], q.weights[2]};
    worst = std::max(worst, std::abs(norm(conic_point(c, w, i / 1000.0)) - 1));
  }
  CHECK(worst < 1e-12);
  // Arcs of every opening, up to almost the whole circle: s = 1 keeps them circular, f >= 2
  // (beyond a half circle) as two spans of positive weights.
  for (double half : {0.1, 0.7, 1.5, std::numbers::pi / 2, 2.0, 2.8, 3.1}) {
    const Vec3 p0{std::cos(-half), std::sin(-half), 0}, p1{std::cos(half), std::sin(half), 0};
    const ConicSpans c = conic_spans(p0, {1, 0, 0}, p1, 1);
    if (std::abs(half - std::numbers::pi / 2) > 1e-9) CHECK(c.spans == (half > 1.6 ? 2 : 1));
    double off = 0;
    for (int s = 0; s < c.spans; ++s) {
      const Vec3 ctl[3] = {c.controls[2 * s], c.controls[2 * s + 1], c.controls[2 * s + 2]};
      const double w[3] = {c.weights[2 * s], c.weights[2 * s + 1], c.weights[2 * s + 2]};
      CHECK(w[1] > 0);
      for (int i = 0; i <= 200; ++i)
        off = std::max(off, std::abs(norm(conic_point(ctl, w, i / 200.0)) - 1));
    }
    CAPTURE(half);
    CHECK(off < 1e-12);
  }
  // s = 0: a parabola, weight 1, control 2M - Q.
  const ConicSpans parabola = conic_spans({0, 0, 0}, {2, 1, 0}, {4, 0, 0}, 0);
  CHECK(parabola.weights[1] == 1);
  CHECK(parabola.controls[1] == Vec3{2, 2, 0});
  // b = 1/2 here. s < 0 with f > 0: a hyperbola (weight above 1) through M at t = 1/2; f < 0:
  // its wrong half, the two lines.
  CHECK(conic_spans({0, 0, 0}, {2, 1, 0}, {4, 0, 0}, -5).lines);           // f = -1/4
  const ConicSpans h2 = conic_spans({0, 0, 0}, {2, 1, 0}, {4, 0, 0}, -2);  // f = 1/2
  REQUIRE_FALSE(h2.lines);
  CHECK(h2.weights[1] == 3);
  const Vec3 c3[3] = {h2.controls[0], h2.controls[1], h2.controls[2]};
  const double w3[3] = {1, 3, 1};
  CHECK(norm(conic_point(c3, w3, 0.5) - Vec3{2, 1, 0}) < 1e-15);
  // f = 0 exactly, a chord of zero length, and overflowing numbers: the two lines.
  CHECK(conic_spans({0, 0, 0}, {2, 1, 0}, {4, 0, 0}, -4).lines);
  CHECK(conic_spans({1, 1, 1}, {2, 1, 0}, {1, 1, 1}, 1).lines);
  CHECK(conic_spans({0, 0, 0}, {2, 1e200, 0}, {4, 0, 0}, 1e200).lines);
  // conic_shape inverts conic_spans.
  for (double s : {1.0, 0.0, -0.5, 0.3, 2.5}) {
    const ConicSpans c = conic_spans({0, 0, 0}, {1.5, 1, 0.25}, {4, 0, 0}, s);
    REQUIRE(c.spans == 1);
    const ConicShape shape =
        conic_shape(c.controls[0], c.controls[1], c.controls[2], 1, c.weights[1], 1);
    CHECK(shape.shape == doctest::Approx(s).epsilon(1e-12));
    CHECK(norm(shape.mid - Vec3{1.5, 1, 0.25}) < 1e-12);
    // Scaled weights are the same curve.
    const ConicShape scaled =
        conic_shape(c.controls[0], c.controls[1], c.controls[2], 4, 2 * c.weights[1] * 3, 9);
    CHECK(scaled.shape == doctest::Approx(s).epsilon(1e-12));
  }
}

TEST_CASE("the writer's lines have the format's field widths") {
  Drawing3 d;
  const double line[] = {0, 0, 0, 10, 0, 0};
  d.add_polyline(Vec3View(line, 2), {.pen = 2, .dash = Dash::dashed});
  const double arc[] = {10, 0, 0, 10, 10, 0, 0, 10, 0};
  const double w[] = {1, std::sqrt(0.5), 1};
  d.add_curve(2, Vec3View(arc, 3), w, {.pen = 3, .dash = Dash::chain});
  d.add_mark({5, 5, 5}, MarkShape::diamond, 3);
  d.add_text({1, 2, 3}, "A TEXT", 1, {.pen = 4});
  const std::string text = write_duct(duct_picture(d, {"ARC", "22 SEP 1987 09:55:50", "A TITLE"}));
  CHECK(text ==
        "IGDS PICTURE FILE ARC 22 SEP 1987 09:55:50\n"
        "A TITLE\n"
        " *\n"
        "      7     3    -1     4     7     0     3     0     0     0\n"
        "     0.0000   10.0000    0.0000   10.0000    0.0000    5.0000    0.0000\n"
        "        4097      2\n"
        "        6658      3\n"
        "        2312      1\n"
        "        8200      1\n"
        "  0.0000000E+00  0.0000000E+00  0.0000000E+00     0.0000     0.0000\n"
        "  0.1000000E+02  0.0000000E+00  0.0000000E+00     0.0000     0.0000\n"
        "  0.1000000E+02  0.0000000E+00  0.0000000E+00     0.0000     0.0000\n"
        "  0.7071068E+01  0.7071068E+01  0.0000000E+00     1.0000     0.0000\n"
        "  0.0000000E+00  0.1000000E+02  0.0000000E+00     0.0000     0.0000\n"
        "  0.5000000E+01  0.5000000E+01  0.5000000E+01     0.0000     0.0000\n"
        "  0.1000000E+01  0.2000000E+01  0.3000000E+01     0.0000     0.0000\n"
        "      1     0\n"
        "        7  6  4 1   0.000   3.000                 A TEXT\n");
}

TEST_CASE("records whose numbers overflow their fields are still read back") {
  // Reals stay in their F10.4 columns whatever their magnitude (a point anywhere and an exponent
  // are what Fw.d reads); an integer that overflows its field loses the columns, and every number
  // of its record gets a blank before it.
  DuctPicture p = read_duct(small_picture);
  p.reals = {0.00001, 18772.23, -1234.5678, 123456.789, 0, 5, 1e200};
  p.counters[7] = -12345;
  std::string text = write_duct(p);
  CHECK(text.find("\n      1.E-518772.2300-1234.5678123456.789    0.0000    5.0000    1.E200\n") !=
        std::string::npos);
  DuctPicture back = read_duct(text);
  CHECK(back.reals == p.reals);
  CHECK(back.counters == p.counters);
  p.counters[7] = 1234567;
  text = write_duct(p);
  CHECK(text.find("\n  4 3 -1 2 5 0 3 1234567 0 0\n") != std::string::npos);
  CHECK(read_duct(text).counters == p.counters);
  // Texts keep their column 51 whatever their numbers.
  p.counters[0] = 6;
  p.texts = {{5, -1000, 77777, 725.5, 1e6, "TEXT"}};
  p.dimensions = {{{1, 1, 0, 1, 2, 0, 5, 123456789, 1, 2, 0}, 0}};
  back = read_duct(write_duct(p));
  REQUIRE(back.texts.size() == 1);
  CHECK(back.texts[0] == DuctText{5, -99, 99, 5.5, 9999.999, "TEXT"});
  CHECK(back.dimensions == p.dimensions);
  CHECK_THROWS_AS(read_duct(write_duct(p) + "x"), DuctError);
}

TEST_CASE("a drawing written and read back gives the same items") {
  Drawing3 d;
  const double open[] = {0, 0, 0, 3, 1, 2, 5, -2, 4};
  d.add_polyline(Vec3View(open, 3), {.pen = 1});
  const double square[] = {0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  d.add_polyline(Vec3View(square, 4), {.pen = 2, .dash = Dash::dashed}, {}, true);
  const double cubic[] = {0, 0, 0, 1, 2, 0, 3, 2, 1, 4, 0, 1, 5, -2, 1, 7, -2, 0, 8, 0, 0};
  d.add_curve(3, Vec3View(cubic, 7), {}, {.pen = 3, .dash = Dash::chain});
  const double quarter[] = {1, 0, 0, 1, 1, 0, 0, 1, 0};
  const double qw[] = {1, std::sqrt(0.5), 1};
  d.add_curve(2, Vec3View(quarter, 3), qw, {.pen = 4});
  const double parabola[] = {0, 0, 2, 1, 3, 2, 2, 0, 2, 3, -1, 2, 4, 0, 2};
  d.add_curve(2, Vec3View(parabola, 5));
  d.add_mark({1, 1, 1}, MarkShape::cross, duct_mark_size);
  d.add_mark({2, 1, 1}, MarkShape::cross, duct_mark_size);
  d.add_mark({3, 1, 1}, MarkShape::plus, duct_mark_size, {.pen = 2});
  d.add_mark({4, 1, 1}, MarkShape::square, duct_mark_size);
  d.add_mark({5, 1, 1}, MarkShape::diamond, duct_mark_size);
  d.add_text({0, 5, 0}, "HELLO", 1, {.pen = 2});
  d.add_text({0, 6, 0}, "A TEXT LONGER THAN THIRTY CHARACTERS, ON TWO LINES", 1);

  const std::string text = write_duct(duct_picture(d, {"ROUND", "01 JAN 1975 00:00:00", ""}));
  const Drawing3 back = duct_drawing(read_duct(text));
  REQUIRE(back.size() == d.size());
  for (std::size_t k = 0; k < d.size(); ++k) {
    CAPTURE(k);
    const auto& a = d.items()[k];
    const auto& b = back.items()[k];
    CHECK(a.kind == b.kind);
    CHECK(a.style == b.style);
    CHECK(a.shape == b.shape);
    CHECK(a.degree == b.degree);
    auto pa = d.points(a);
    auto pb = back.points(b);
    const std::size_t closing = a.closed ? 1 : 0;
    REQUIRE(pb.size() == pa.size() + closing);
    for (std::size_t i = 0; i < pb.size(); ++i)
      CHECK(near(pb[i], pa[i % pa.size()], 5e-7 * std::max(1.0, norm(pa[i % pa.size()]))));
    const auto wa = d.weights(a), wb = back.weights(b);
    for (std::size_t i = 0; i < wa.size(); ++i)
      CHECK(wb[i] == doctest::Approx(wa[i]).epsilon(1e-6));
    if (a.kind == Drawing3::Kind::text) CHECK(d.text(a) == back.text(b));
  }
  // The picture itself comes back the same: numbers read print to the same digits.
  const DuctPicture once = read_duct(text);
  CHECK(read_duct(write_duct(once)) == once);
  CHECK(write_duct(read_duct(write_duct(once))) == write_duct(once));
}

TEST_CASE("a surface's picture: counters, the box and exact spans") {
  const TestSurface t = golden_surface();
  const Drawing3 d = surface_curves(t.input, t.surface);
  const DuctPicture p = duct_picture(d, {"SURFACE", "22 SEP 1987 09:55:50", "SURFACE"});
  // 13 curves and 10 stringers, the border, 18 tangents, one instruction for the 20 points.
  CHECK(p.counters[0] == 4);
  CHECK(p.counters[3] == 13 + 10 + 1 + 18 + 1);
  CHECK(std::size_t(p.counters[4]) == p.pixel_count());
  CHECK(p.pixel_count() == 13 * 10 + 10 * 13 + 15 + 2 * 18 + 20);
  CHECK(p.counters[5] == 0);
  CHECK(p.counters[6] == 3);
  // R1..R6 hold the curves and are tight to F10.4's last digit: dense samples of every span
  // lie inside, and come within 1e-4 of each limit.
  std::array<double, 6> seen = {INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const auto& item : d.items()) {
    const auto pts = d.points(item);
    auto see = [&](Vec3 v) {
      const double c[3] = {v.x, v.y, v.z};
      for (int k = 0; k < 3; ++k) {
        seen[2 * k] = std::min(seen[2 * k], c[k]);
        seen[2 * k + 1] = std::max(seen[2 * k + 1], c[k]);
      }
    };
    if (item.kind == Drawing3::Kind::curve) {
      for (std::size_t s = 0; s + 3 < pts.size(); s += 3) {
        const Vec3 c[4] = {pts[s], pts[s + 1], pts[s + 2], pts[s + 3]};
        for (int i = 0; i <= 400; ++i) see(bezier3(c, i / 400.0));
      }
    } else {
      for (Vec3 v : pts) see(v);
    }
  }
  for (int k = 0; k < 6; ++k) {
    CAPTURE(k);
    if (k % 2 == 0) {
      CHECK(p.reals[k] <= seen[k]);
      CHECK(p.reals[k] > seen[k] - 1.01e-4);
    } else {
      CHECK(p.reals[k] >= seen[k]);
      CHECK(p.reals[k] < seen[k] + 1.01e-4);
    }
  }
  // Read back, it draws the same spans (to E14.7's seven digits): the same vectors.
  const Drawing3 back = duct_drawing(read_duct(write_duct(p)));
  REQUIRE(back.size() == d.size());
  for (std::size_t k = 0; k < d.size(); ++k) {
    const auto a = d.points(d.items()[k]);
    const auto b = back.points(back.items()[k]);
    const std::size_t closing = d.items()[k].closed ? 1 : 0;
    REQUIRE(b.size() == a.size() + closing);
    for (std::size_t i = 0; i < a.size(); ++i)
      CHECK(near(b[i], a[i], 5e-7 * std::max(1.0, norm(a[i]))));
  }
}

namespace {

// A drawing with every kind of item DUCT has, about 1 wide: the golden surface's curves and
// stringers (flat at their ends, where the written spans can pass their end pixels), a quarter
// circle, a closed polyline, marks and texts, one longer than 30 characters.
Drawing3 every_kind() {
  const TestSurface t = golden_surface();
  Drawing3 d = moved(surface_curves(t.input, t.surface), 1 / 75.0, {0, 0, 0});
  const double quarter[] = {1, 0, 0.2, 0.7071067811865476, 0.7071067811865476, 0.2, 0, 1, 0.2};
  const double qw[] = {1, std::sqrt(0.5), 1};
  d.add_curve(2, Vec3View(quarter, 3), qw, {.pen = 3});
  const double square[] = {-0.1, -0.1, 0, 1.1, -0.1, 0, 1.1, 1.1, 0.1, -0.1, 1.1, 0.1};
  d.add_polyline(Vec3View(square, 4), {.pen = 2, .dash = Dash::dashed}, {}, true);
  d.add_mark({0.5, 0.5, -0.05}, MarkShape::cross, duct_mark_size);
  d.add_mark({0.25, 0.75, 0.05}, MarkShape::diamond, duct_mark_size, {.pen = 4});
  d.add_text({0.3, 0.3, 0.3}, "HULL", 1, {.pen = 2});
  d.add_text({0.6, 0.1, -0.2}, "A TEXT LONGER THAN THIRTY CHARACTERS, ON TWO LINES", 1);
  return d;
}

// The magnitudes checked: scales from 1e-6 to 1e9, each at the origin and moved off it.
struct Magnitude {
  double scale;
  Vec3 by;
};
std::vector<Magnitude> magnitudes() {
  std::vector<Magnitude> all;
  for (double s : {1e-6, 3e-4, 0.05, 1.0, 75.0, 1234.5, 1e5, 7.5e6, 1e9}) {
    all.push_back({s, {0, 0, 0}});
    all.push_back({s, {0.7123 * s, -1.45678 * s, 0.2 * s}});
    all.push_back({s, {-13.1 * s, 9.87654 * s, -2.5 * s}});
  }
  return all;
}

}  // namespace

TEST_CASE("every record is in DUCT's columns at any magnitude, and the limits hold what is drawn") {
  const Drawing3 base = every_kind();
  for (const Magnitude& m : magnitudes()) {
    CAPTURE(m.scale);
    CAPTURE(m.by);
    const Drawing3 d = moved(base, m.scale, m.by);
    const DuctPicture p = duct_picture(d, {"HULL", "22 SEP 1987 09:55:50", "HULL"});
    const std::string text = write_duct(p);
    CHECK(streamed(d, DuctHeader{"HULL", "22 SEP 1987 09:55:50", "HULL"}, DuctView{}) == text);
    const DuctPicture fixed = read_columns(text);
    const DuctPicture read = read_duct(text);
    CHECK(fixed.counters == read.counters);
    CHECK(fixed.reals == read.reals);
    CHECK(fixed.reals == p.reals);  // the limits are written exactly
    CHECK(fixed.instructions == read.instructions);
    CHECK(fixed.xyz == read.xyz);
    CHECK(fixed.tu == read.tu);
    CHECK(fixed.texts == read.texts);
    // Every pixel on what is drawn lies inside the limits, as read; so does every point of the
    // spans drawn from them (to the rounding of their evaluation); and the limits are tight:
    // within a step of their last digit (1e-4 of their magnitude at most) of what is drawn.
    const Drawing3 drawn = duct_drawing(fixed);
    std::array<double, 6> seen = {INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY};
    const double most =
        std::max({std::abs(p.reals[0]), std::abs(p.reals[1]), std::abs(p.reals[2]),
                  std::abs(p.reals[3]), std::abs(p.reals[4]), std::abs(p.reals[5])});
    std::size_t outside = 0;
    auto see = [&](Vec3 v, double slack) {
      const double c[3] = {v.x, v.y, v.z};
      for (int k = 0; k < 3; ++k) {
        seen[2 * k] = std::min(seen[2 * k], c[k]);
        seen[2 * k + 1] = std::max(seen[2 * k + 1], c[k]);
        if (c[k] < p.reals[2 * k] - slack || c[k] > p.reals[2 * k + 1] + slack) ++outside;
      }
    };
    for (const auto& item : drawn.items()) {
      const auto pts = drawn.points(item);
      const auto w = drawn.weights(item);
      if (item.kind != Drawing3::Kind::curve) {
        for (Vec3 v : pts) see(v, 0);
        continue;
      }
      const std::size_t deg = item.degree;
      for (std::size_t s = 0; s + deg < pts.size(); s += deg) {
        see(pts[s], 0);
        see(pts[s + deg], 0);
        for (int i = 1; i < 200; ++i) {
          const double t = i / 200.0;
          if (deg == 3) {
            const Vec3 c[4] = {pts[s], pts[s + 1], pts[s + 2], pts[s + 3]};
            see(bezier3(c, t), 1e-14 * most);
          } else {
            const Vec3 c[3] = {pts[s], pts[s + 1], pts[s + 2]};
            const double ws[3] = {w[s], w[s + 1], w[s + 2]};
            see(conic_point(c, ws, t), 1e-14 * most);
          }
        }
      }
    }
    CHECK(outside == 0);
    for (int k = 0; k < 6; ++k) {
      CAPTURE(k);
      CHECK(std::abs(p.reals[k] - seen[k]) <= 1.01e-4 * std::max(1.0, std::abs(seen[k])));
    }
  }
}

TEST_CASE("gfortran reads the pictures with DUCT's own formats at any magnitude") {
  IGDS_SKIP_UNLESS(test::have_program("gfortran"), "gfortran is not installed");
  test::TempDir dir;
  const std::string program = R"(program duct
  implicit none
  integer :: i(10), k, code, npix, nt, nd, j1, j2, j3, j4
  real(8) :: r(7), x(3), tu(2), s1, s2
  character(len=200) :: line
  character(len=80) :: c
  open(10, file='PIC', status='old')
  open(11, file='OUT', status='replace')
  do
    read(10, '(A)') line
    if (trim(adjustl(line)) == '*') exit
  end do
  read(10, '(1X,10I6)') i
  read(10, '(1X,7F10.4)') r
  write(11, '(10I12)') i
  write(11, '(7ES26.17E3)') r
  do k = 1, i(4)
    read(10, '(1X,I11,1X,I6)') code, npix
    write(11, '(2I12)') code, npix
  end do
  do k = 1, i(5)
    if (mod(i(1), 2) == 1) then
      read(10, '(3(1X,E14.7),2(1X,F10.4))') x, tu
      write(11, '(5ES26.17E3)') x, tu
    else
      read(10, '(3(1X,E14.7))') x
      write(11, '(3ES26.17E3)') x
    end if
  end do
  if (mod(i(1) / 2, 2) == 1) then
    read(10, '(1X,2I6)') nt, nd
    write(11, '(2I12)') nt, nd
    do k = 1, nt
      c = ' '
      read(10, '(1X,I8,I3,I3,I2,2F8.3,17X,A)') j1, j2, j3, j4, s1, s2, c
      if (j2 > 30) read(10, '(1X,A)') c(31:)
      write(11, '(4I12,2ES26.17E3)') j1, j2, j3, j4, s1, s2
      write(11, '(A,A)') 'T:', c(1:j2)
    end do
  end if
end program duct
)";
  test::write_file(dir.path() / "duct.f90", program);
  const auto built =
      test::run({"gfortran", "-ffree-line-length-none", "-o", (dir.path() / "duct").string(),
                 (dir.path() / "duct.f90").string()});
  REQUIRE_MESSAGE(built.status == 0, built.err);
  const Drawing3 base = every_kind();
  for (const Magnitude& m : magnitudes()) {
    CAPTURE(m.scale);
    CAPTURE(m.by);
    const std::string text =
        write_duct(duct_picture(moved(base, m.scale, m.by), {"HULL", "22 SEP 1987", ""}));
    test::write_file(dir.path() / "PIC", text);
    test::RunOptions in_dir;
    in_dir.cwd = dir.path();
    const auto ran = test::run({(dir.path() / "duct").string()}, in_dir);
    REQUIRE_MESSAGE(ran.status == 0, ran.err);
    // What gfortran read, number by number, against read_duct.
    const DuctPicture p = read_duct(text);
    std::vector<double> ours(p.counters.begin(), p.counters.end());
    ours.insert(ours.end(), p.reals.begin(), p.reals.end());
    for (const auto& in : p.instructions)
      ours.insert(ours.end(), {double(in.code()), double(in.pixels)});
    for (std::size_t k = 0; k < p.pixel_count(); ++k) {
      ours.insert(ours.end(), p.xyz.begin() + std::ptrdiff_t(3 * k),
                  p.xyz.begin() + std::ptrdiff_t(3 * k + 3));
      if (p.has_tu()) ours.insert(ours.end(), {p.tu[2 * k], p.tu[2 * k + 1]});
    }
    std::vector<std::string> our_texts;
    if (p.has_texts()) {
      ours.insert(ours.end(), {double(p.texts.size()), double(p.dimensions.size())});
      for (const auto& t : p.texts) {
        ours.insert(ours.end(), {double(t.pixel), double(t.text.size()), double(t.colour),
                                 double(t.units), t.angle, t.height});
        our_texts.push_back(t.text);
      }
    }
    std::vector<double> theirs;
    std::vector<std::string> their_texts;
    std::istringstream out(test::read_file(dir.path() / "OUT"));
    for (std::string line; std::getline(out, line);) {
      if (line.rfind("T:", 0) == 0) {
        their_texts.push_back(line.substr(2));
        continue;
      }
      std::istringstream numbers(line);
      for (std::string n; numbers >> n;) theirs.push_back(std::strtod(n.c_str(), nullptr));
    }
    CHECK(theirs == ours);
    CHECK(their_texts == our_texts);
  }
}

TEST_CASE("the picture of an image is a projected picture at z = 0") {
  const TestSurface t = golden_surface();
  const Drawing3 space = surface_curves(t.input, t.surface);
  const Vec3 centre = bounding_box(space).centre();
  const Drawing2 plane = project(space, {Projection::assonometric, {110, 130, 120}}, centre);
  const DuctPicture p =
      duct_picture(plane, {"IMAGE", "22 SEP 1987 09:55:50", ""}, Projection::assonometric);
  CHECK(p.counters[1] == 3);
  CHECK(p.counters[6] == 2);
  CHECK(p.counters[7] == 2);
  CHECK(p.reals[4] == 0);
  CHECK(p.reals[5] == 0);
  for (std::size_t k = 0; k < p.pixel_count(); ++k) CHECK(p.xyz[3 * k + 2] == 0);
  const Drawing3 back = duct_drawing(read_duct(write_duct(p)));
  REQUIRE(back.size() == plane.size());
  for (std::size_t k = 0; k < plane.size(); ++k) {
    const auto a = plane.points(plane.items()[k]);
    const auto b = back.points(back.items()[k]);
    REQUIRE(b.size() >= a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      CHECK(near(b[i], {a[i].x, a[i].y, 0}, 5e-7 * std::max(1.0, std::hypot(a[i].x, a[i].y))));
  }
}

TEST_CASE("rational cubics of a perspective become straight lines close to them") {
  const TestSurface t = golden_surface();
  const Drawing3 space = surface_curves(t.input, t.surface);
  const Vec3 centre = bounding_box(space).centre();
  const Drawing2 plane = project(space, {Projection::conic, {60, -80, 50}}, centre);
  const DuctPicture p = duct_picture(plane, {"CONIC", "", ""}, Projection::conic);
  CHECK(p.counters[5] == -2);  // straight lines only
  CHECK(streamed(plane, DuctHeader{"CONIC", "", ""}, Projection::conic) == write_duct(p));
  // Every curve's samples lie within 1e-5 of the picture's extent (plus the seven digits of the
  // pixels) of its polyline.
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (const auto& item : plane.items())
    for (Point2 v : plane.points(item))
      lo_x = std::min(lo_x, v.x), hi_x = std::max(hi_x, v.x), lo_y = std::min(lo_y, v.y),
      hi_y = std::max(hi_y, v.y);
  const double extent = std::max(hi_x - lo_x, hi_y - lo_y);
  std::size_t pixel = 0, checked = 0;
  // Item k is instruction k up to the marks (which share one).
  for (std::size_t k = 0; k < plane.size() && plane.items()[k].kind != Drawing2::Kind::mark; ++k) {
    const auto& item = plane.items()[k];
    const std::size_t n = p.instructions[k].pixels;
    if (item.kind == Drawing2::Kind::curve) {
      const auto c = plane.points(item);
      const auto w = plane.weights(item);
      REQUIRE(w.size() == c.size());
      double worst = 0;
      for (std::size_t s = 0; s + 3 < c.size(); s += 3) {
        for (int i = 0; i <= 50; ++i) {
          const double tt = i / 50.0, u = 1 - tt;
          const double b[4] = {u * u * u, 3 * u * u * tt, 3 * u * tt * tt, tt * tt * tt};
          double x = 0, y = 0, h = 0;
          for (int j = 0; j < 4; ++j) {
            const double wj = w[s + std::size_t(j)] * b[j];
            x += wj * c[s + std::size_t(j)].x, y += wj * c[s + std::size_t(j)].y, h += wj;
          }
          x /= h, y /= h;
          double best = INFINITY;
          for (std::size_t q = pixel; q + 1 < pixel + n; ++q) {
            const double ax = p.xyz[3 * q], ay = p.xyz[3 * q + 1], bx = p.xyz[3 * q + 3],
                         by = p.xyz[3 * q + 4];
            const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
            const double f =
                l2 > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / l2, 0.0, 1.0) : 0;
            best = std::min(best, std::hypot(x - ax - f * dx, y - ay - f * dy));
          }
          worst = std::max(worst, best);
        }
      }
      CHECK(worst <= 1e-5 * extent + 1e-6 * std::max(std::abs(hi_x), std::abs(hi_y)) * 10);
      ++checked;
    }
    pixel += n;
  }
  CHECK(checked == 23);
}

TEST_CASE("nothing at all is one invisible pixel; points that are not finite are refused") {
  const DuctPicture empty = duct_picture(Drawing3{}, {"EMPTY", "", ""});
  CHECK(empty.instructions.size() == 1);
  CHECK(empty.instructions[0].pen == DuctPen::invisible);
  CHECK(duct_drawing(read_duct(write_duct(empty))).empty());
  Drawing3 bad;
  const double line[] = {0, 0, 0, NAN, 1, 1};
  bad.add_polyline(Vec3View(line, 2));
  try {
    duct_picture(bad, {"BAD", "", ""});
    FAIL("no refusal");
  } catch (const DataError& e) {
    CHECK(e.problem == DataError::Problem::point_not_finite);
    CHECK(e.number == 1);
  }
  // Written straight from the drawing: refused before a byte is written.
  StringOut out;
  Drawing3 later;
  later.add_polyline(Vec3View(line, 1));
  later.add_polyline(Vec3View(line, 2));
  try {
    write_duct(later, {"BAD", "", ""}, {}, out);
    FAIL("no refusal");
  } catch (const DataError& e) {
    CHECK(e.problem == DataError::Problem::point_not_finite);
    CHECK(e.number == 2);
  }
  CHECK(out.take_text().empty());
  CHECK(streamed(Drawing3{}, DuctHeader{"EMPTY", "", ""}, DuctView{}) == write_duct(empty));
}

TEST_CASE("mutated pictures are read or refused, never more; what is read writes and reads back") {
  const std::string base = hand_written();
  Random random(13);
  int accepted = 0, refused = 0;
  for (int n = 0; n < 3000; ++n) {
    std::string text = base;
    const int mutations = 1 + int(random.uniform(0, 3));
    for (int m = 0; m < mutations; ++m) {
      const std::size_t at = std::size_t(random.uniform(0, double(text.size())));
      const int kind = int(random.uniform(0, 5));
      const char* alphabet = "0123456789 -+.E,*\n";
      const char c = alphabet[std::size_t(random.uniform(0, 18))];
      if (kind == 0) {
        text[at] = c;
      } else if (kind == 1) {
        text.insert(at, 1, c);
      } else if (kind == 2) {
        text.erase(at, std::size_t(random.uniform(1, 40)));
      } else if (kind == 3) {
        text.resize(at);
      } else {
        const std::size_t from = text.rfind('\n', at), to = text.find('\n', at);
        if (from != std::string::npos && to != std::string::npos)
          text.insert(to, text.substr(from, to - from));
      }
    }
    try {
      const DuctPicture p = read_duct(text);
      ++accepted;
      const Drawing3 d = duct_drawing(p);
      CHECK_NOTHROW(read_duct(write_duct(p)));
      const DuctHeader again{"AGAIN", "", "A TITLE"};
      const std::string text = write_duct(duct_picture(d, again));
      CHECK_NOTHROW(read_duct(text));
      // Conics with their T U, Bézier spans, marks and texts alike.
      CHECK(streamed(d, again, DuctView{}) == text);
    } catch (const DuctError& e) {
      ++refused;
      CHECK(e.line >= 1);
    }
  }
  CHECK(accepted > 100);
  CHECK(refused > 100);
}

namespace {

// Cubic chains, lines and marks, 110000 points in all, inside the box [0.4, 0.8] x [0.4, 0.8] x
// [0.45, 0.55] (well inside every_kind()'s): enough for a picture to be laid out and written on
// every core (kernels/parallel.h, text_out.h's put_each).
void add_filler(Drawing3& d) {
  std::vector<double> xyz;
  for (int c = 0; c < 300; ++c) {
    xyz.clear();
    for (int i = 0; i <= 300; ++i)
      xyz.insert(xyz.end(), {0.4 + 0.4 * i / 300, 0.4 + 0.4 * c / 300, 0.5 + 0.05 * std::sin(i)});
    d.add_curve(3, Vec3View(xyz.data(), xyz.size() / 3), {}, {.pen = 1 + c % 3});
  }
  for (int m = 0; m < 19000; ++m)
    d.add_mark({0.4 + 0.4 * (m % 137) / 137, 0.4 + 0.4 * m / 19000, 0.5}, MarkShape::dot, 1,
               {.pen = 2 + m / 5000});
  const double line[] = {0.45, 0.45, 0.5, 0.75, 0.5, 0.52, 0.7, 0.75, 0.48};
  for (int l = 0; l < 300; ++l) d.add_polyline(Vec3View(line, 3), {}, {}, l % 2 == 1);
}

// The pixels a drawing of polylines, polynomial cubics, conic arcs (of 3 controls), marks and
// texts has, in order, as its picture's lines give them: x y z and T of each.
std::vector<double> pixels_of(const Drawing3& d) {
  std::vector<double> out;
  auto put = [&](Vec3 v, double t) {
    for (double x : {v.x, v.y, v.z}) {
      char field[40];
      fortran::put_e_whole(field, x, 14, 7);
      out.push_back(*fortran::read_f({field, 14}, 0, 14, 7));
    }
    out.push_back(t);
  };
  for (const auto& item : d.items()) {
    const auto points = d.points(item);
    if (item.kind == Drawing3::Kind::curve && item.degree == 2) {
      const auto w = d.weights(item);
      REQUIRE(points.size() == 3);
      const ConicShape cs = conic_shape(points[0], points[1], points[2], w[0], w[1], w[2]);
      put(points[0], 0);
      put(cs.mid, cs.shape);
      put(points[2], 0);
      continue;
    }
    for (Vec3 v : points) put(v, 0);
    if (item.closed) put(points[0], 0);
  }
  return out;
}

}  // namespace

TEST_CASE("a picture laid out and written on every core is the picture of its parts") {
  // Every kind of item at two corners, each with a span whose inside reaches below or above all
  // else, and between them more than a core's worth of items well inside: the limits are those
  // of the corners alone, wherever the items are cut between cores.
  Drawing3 base = every_kind();
  const double bulge[] = {0.2, 0.2, 0, 0.3, 0.3, -2, 0.4, 0.3, -2, 0.5, 0.2, 0};
  base.add_curve(3, Vec3View(bulge, 4));
  Drawing3 corners, d;
  add_moved(corners, base, 1, {0, 0, 0});
  add_moved(corners, base, -1, {1.5, 1.5, 0.5});
  add_moved(d, base, 1, {0, 0, 0});
  add_filler(d);
  add_moved(d, base, -1, {1.5, 1.5, 0.5});
  const DuctHeader header{"CORES", "22 SEP 1987 09:55:50", ""};
  const DuctPicture p = duct_picture(d, header);
  CHECK(p.reals == duct_picture(corners, header).reals);
  // The text written from the drawing is the picture kept, and its pixels are the items' points.
  const std::string text = write_duct(p);
  CHECK(streamed(d, header, DuctView{}) == text);
  const DuctPicture back = read_duct(text);
  std::vector<double> read;
  for (std::size_t k = 0; k < back.pixel_count(); ++k)
    read.insert(read.end(),
                {back.xyz[3 * k], back.xyz[3 * k + 1], back.xyz[3 * k + 2], back.tu[2 * k]});
  const std::vector<double> expected = pixels_of(d);
  REQUIRE(read.size() == expected.size());
  std::size_t differ = 0;
  for (std::size_t k = 0; k < read.size(); ++k)
    differ +=
        read[k] == expected[k] || (k % 4 == 3 && std::abs(read[k] - expected[k]) < 1e-4) ? 0 : 1;
  CHECK(differ == 0);
  // In the plane too.
  const Drawing2 plane =
      project(d, {Projection::assonometric, {110, 130, 120}}, bounding_box(d).centre());
  CHECK(streamed(plane, header, Projection::assonometric) ==
        write_duct(duct_picture(plane, header, Projection::assonometric)));
  // The first item that is not finite is refused, whichever core looks at it.
  const double bad[] = {0.5, 0.5, NAN, 0.5, 0.6, 0.5};
  for (bool both : {false, true}) {
    Drawing3 refused;
    if (both) refused.add_polyline(Vec3View(bad, 2));
    add_filler(refused);
    refused.add_polyline(Vec3View(bad, 2));
    try {
      streamed(refused, header, DuctView{});
      FAIL("no refusal");
    } catch (const DataError& e) {
      CHECK(e.number == (both ? 1 : refused.size()));
    }
  }
}

TEST_CASE("golden: the pictures of a small surface") {
  const TestSurface t = golden_surface();
  const Drawing3 d = surface_curves(t.input, t.surface);
  const std::string date = duct_date({1987, 9, 22, 9, 55, 50});
  check_golden("surface_5x4.ductpic",
               write_duct(duct_picture(d, {"SURFACE", date, "SURFACE 5 X 4, INTCU 2, INTST 2"})));
  const Drawing2 plane =
      project(d, {Projection::assonometric, {110, 130, 120}}, bounding_box(d).centre());
  check_golden("surface_5x4_assonometric.ductpic",
               write_duct(duct_picture(plane, {"IMAGE", date, "ASSONOMETRIC 110 130 120"},
                                       Projection::assonometric)));
  // EXPORT DUCT's own way, straight from the drawings: the same files.
  check_golden(
      "surface_5x4.ductpic",
      streamed(d, DuctHeader{"SURFACE", date, "SURFACE 5 X 4, INTCU 2, INTST 2"}, DuctView{}));
  check_golden("surface_5x4_assonometric.ductpic",
               streamed(plane, DuctHeader{"IMAGE", date, "ASSONOMETRIC 110 130 120"},
                        Projection::assonometric));
}

}  // namespace igds::test::exchange
