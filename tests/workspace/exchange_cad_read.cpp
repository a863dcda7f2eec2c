// The CAD surface readers of IMPORT (workspace/exchange/cad_read.h): the surfaces igds writes read
// back and evaluated at the INTPN parameters, derivatives included; a rational surface; forged
// files refused with their reason, truncated ones at every length never more than refused.
#include "workspace/exchange/cad_read.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "tests/workspace/exchange_support.h"
#include "workspace/exchange/iges.h"
#include "workspace/exchange/step.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/fit.h"

namespace igds::test::exchange {

namespace {

const CadHeader header{"HULL", "HULL.IGS", {1987, 9, 22, 9, 55, 50}, "", ""};

// The largest distance between the surface read and INTPN at its parameters (u along the curves
// from 0 to NOSTR - 1, v along the stringers), relative to the largest coordinate; and between
// the derivatives at the input points and the Bézier net's (3 times a control leg, the knots'
// spacing being 1).
double worst_error(const TestSurface& t, const CadSurface& s) {
  const auto& in = t.input;
  const std::size_t nc = in.nocur, ns = in.nostr, ic = in.intcu, is = in.intst;
  const GridShape g = intpn_shape(in.nocur, in.nostr, in.intcu, in.intst);
  double worst = 0;
  for (std::size_t k = 0; k < g.rows * g.cols; ++k) {
    const std::size_t row = k / g.cols, col = k % g.cols;
    const std::size_t i = std::min(row / (ic + 1), nc - 2), j = std::min(col / (is + 1), ns - 2);
    const double u = double(j) + double(col - j * (is + 1)) / double(is + 1);
    const double v = double(i) + double(row - i * (ic + 1)) / double(ic + 1);
    const Vec3 expected = Vec3::load(t.surface.intpn.data() + 3 * k);
    worst = std::max(worst, norm(evaluate(s, u, v).p - expected));
  }
  const BezierNet net = surface_net(t.input, t.surface.patches);
  for (std::size_t i = 0; i < nc; ++i) {
    const SurfacePoint first = evaluate(s, 0, double(i));
    worst = std::max(worst, norm(first.du - 3 * (net.at(3 * i, 1) - net.at(3 * i, 0))));
  }
  return worst / largest_coordinate(t.surface.intpn);
}

}  // namespace

TEST_CASE("IMPORT's readers: igds's IGES and STEP surfaces read back exactly") {
  // Nets of 10, 88 and 178 rows.
  std::vector<TestSurface> surfaces{golden_surface(), test_surface(30, 20, 1, 2),
                                    test_surface(60, 4, 0, 1)};
  TestSurface pole = test_surface(4, 5, 1, 1);
  for (int j = 0; j < 5; ++j) std::fill_n(pole.inppn.data() + 3 * j, 3, 1.0);
  pole.surface = interpolate(pole.input);
  surfaces.push_back(std::move(pole));
  for (const TestSurface& t : surfaces) {
    CAPTURE(t.input.nocur);
    const CadSurface iges = read_iges_surface(write_iges(t.input, t.surface.patches, header));
    CHECK(iges.degree_u == 3);
    CHECK(iges.count_u == std::size_t(3 * (t.input.nostr - 1) + 1));
    CHECK(iges.count_v == std::size_t(3 * (t.input.nocur - 1) + 1));
    CHECK(iges.weights.empty());
    CHECK(worst_error(t, iges) < 1e-12);
    const CadSurface step = read_step_surface(write_step(t.input, t.surface.patches, header));
    CHECK(step.controls == iges.controls);
    CHECK(step.knots_u == iges.knots_u);
    CHECK(step.knots_v == iges.knots_v);
    CHECK(worst_error(t, step) < 1e-12);
    // With FACES the first surface is patch 1, on [0, 1] x [0, 1].
    const CadSurface patch =
        read_iges_surface(write_iges(t.input, t.surface.patches, header, SurfaceForm::patches));
    CHECK(patch.count_u == 4);
    CHECK(patch.u1 == 1);
    CHECK(norm(evaluate(patch, 0.5, 0.5).p - evaluate(iges, 0.5, 0.5).p) <=
          1e-13 * largest_coordinate(t.surface.intpn));
  }
}

TEST_CASE("IMPORT's readers: a rational STEP surface, a quarter of a cylinder") {
  // Degree 2 around (weights 1, sqrt(2)/2, 1), degree 1 along z; OpenCASCADE's complex form.
  const std::string w = fmt::format("{:.17g}", std::sqrt(0.5));
  const std::string text =
      "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n"
      "#1 = CARTESIAN_POINT('',(1.,0.,0.));\n#2 = CARTESIAN_POINT('',(1.,0.,2.));\n"
      "#3 = CARTESIAN_POINT('',(1.,1.,0.));\n#4 = CARTESIAN_POINT('',(1.,1.,2.));\n"
      "#5 = CARTESIAN_POINT('',(0.,1.,0.));\n#6 = CARTESIAN_POINT('',(0.,1.,2.));\n"
      "#7 = ( BOUNDED_SURFACE() B_SPLINE_SURFACE(2,1,((#1,#2),(#3,#4),(#5,#6)),.UNSPECIFIED.,"
      ".F.,.F.,.F.) B_SPLINE_SURFACE_WITH_KNOTS((3,3),(2,2),(0.,1.),(0.,2.),.UNSPECIFIED.)\n"
      "GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(((1.,1.),(" +
      w + "," + w +
      "),(1.,1.))) REPRESENTATION_ITEM('') SURFACE() );\nENDSEC;\nEND-ISO-10303-21;\n";
  const CadSurface s = read_step_surface(text);
  CHECK(s.degree_u == 2);
  CHECK(s.degree_v == 1);
  CHECK(s.weights.size() == 6);
  for (double u : {0.0, 0.1, 0.5, 0.77, 1.0})
    for (double v : {0.0, 1.5, 2.0}) {
      const SurfacePoint p = evaluate(s, u, v);
      CHECK(std::abs(std::hypot(p.p.x, p.p.y) - 1) < 1e-15);
      CHECK(std::abs(p.p.z - v) < 1e-15);
      CHECK(std::abs(dot(p.du, {p.p.x, p.p.y, 0})) < 1e-14);  // tangent to the circle
      CHECK(norm(p.dv - Vec3{0, 0, 1}) < 1e-15);
    }
  // The derivative at u = 0: 2 w1 / w0 (P1 - P0) = sqrt(2) (0, 1, 0).
  CHECK(norm(evaluate(s, 0, 0).du - Vec3{0, std::sqrt(2.0), 0}) < 1e-15);
}

TEST_CASE("IMPORT's readers: forged files refused with their reason, truncated ones too") {
  const TestSurface t = golden_surface();
  const std::string iges = write_iges(t.input, t.surface.patches, header);
  const std::string step = write_step(t.input, t.surface.patches, header);
  auto reason_iges = [](const std::string& text) {
    try {
      read_iges_surface(text);
    } catch (const CadReadError& e) {
      return std::string(e.what());
    }
    return std::string("READ");
  };
  auto reason_step = [](const std::string& text) {
    try {
      read_step_surface(text);
    } catch (const CadReadError& e) {
      return std::string(e.what());
    }
    return std::string("READ");
  };
  auto replaced = [](std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    return text;
  };
  CHECK(reason_iges(iges) == "READ");
  CHECK(reason_step(step) == "READ");
  // IGES: counts checked against the file before anything is made of them.
  // (The knots written 0 instead of 0. leave room for the counts: records stay 80 wide.)
  CHECK(reason_iges(replaced(iges, "128,9,12,3,3,0,0,1,0,0,0.,0.,0.,0.,",
                             "128,9999,999,3,3,0,0,1,0,0,0,0,0,0,")) ==
        "10000 X 1000 CONTROLS CANNOT BE IN 8192 BYTES");
  CHECK(reason_iges(replaced(iges, "128,9,12,", "128,9,13,")) ==
        "ENTITY 128 HAS 565 PARAMETERS, NOT 606");
  CHECK(reason_iges(replaced(iges, "128,9,12,3,3", "128,9,12,0,3")) ==
        "ENTITY 128: K1 9 K2 12 M1 0 M2 3");
  CHECK(reason_iges(replaced(iges, "128,9,12,3,3,0,0,1,0,0,0.,", "128,9,12,3,3,0,0,1,0,0,x.,")) ==
        "ENTITY 128: A KNOT IS NOT A NUMBER");
  CHECK(reason_iges(replaced(iges, "128,9,12,3,3,0,0,1,0,0,0.,", "128,9,12,3,3,0,0,1,0,0,9.,")) ==
        "THE KNOTS IN U DECREASE");
  CHECK(reason_iges(replaced(iges, "     128       1", "     126       1")) ==
        "NO B-SPLINE SURFACE (ENTITY 128) IN THE FILE");
  CHECK(reason_iges(replaced(iges, "     128       1", "     128    9999")) ==
        "DIRECTORY ENTRY 1: ITS PARAMETER LINES ARE NOT IN THE FILE");
  CHECK(reason_iges(replaced(iges, "S      1\n", "\n")) ==
        "LINE 1: 72 COLUMNS, AN IGES RECORD HAS 80");
  CHECK(reason_iges("") == "NOT AN IGES FILE (NO G, D OR P SECTION)");
  // STEP.
  CHECK(reason_step(replaced(step, "B_SPLINE_SURFACE_WITH_KNOTS('SURFACE',3,3,",
                             "B_SPLINE_SURFACE_WITH_KNOTS('SURFACE',0,3,")) ==
        "STEP: DEGREES 0 AND 3 (1 TO 25)");
  CHECK(reason_step(replaced(step, "(#15,#25,", "(#999999,#25,")) ==
        "STEP: CONTROL POINT #999999 IS NOT IN THE FILE");
  CHECK(reason_step(replaced(step, "(#15,#25,", "(#25,")) ==
        "STEP: THE CONTROL POINTS ARE NOT A RECTANGLE");
  CHECK(reason_step(replaced(step, "(#15,#25,", "(#13,#25,")) ==
        "STEP: #13 IS NOT A CARTESIAN_POINT");
  CHECK(reason_step(replaced(step, "(4,3,3,4)", "(4,3,3,5)")) ==
        "STEP: A KNOT MULTIPLICITY IS NOT POSSIBLE");
  CHECK(reason_step(replaced(step, "(4,3,3,4)", "(4,3,4)")) ==
        "STEP: AS MANY KNOT MULTIPLICITIES AS KNOTS ARE DUE");
  CHECK(reason_step(replaced(step, "DATA;", "DATA")) ==
        "NOT A STEP FILE (ISO-10303-21; AND DATA; ARE DUE)");
  CHECK(reason_step(replaced(step, "B_SPLINE_SURFACE_WITH_KNOTS", "B_SPLINE_SURFACE_WITH_KNOT")) ==
        "NO B-SPLINE SURFACE (B_SPLINE_SURFACE_WITH_KNOTS) IN THE FILE");
  CHECK(reason_step(replaced(step, "#1=", "#2=")) == "STEP: #2 IS DEFINED TWICE");
  std::string nested = "ISO-10303-21;\nDATA;\n#1=B_SPLINE_SURFACE_WITH_KNOTS('',3,3,";
  nested += std::string(10000, '(');
  CHECK(reason_step(nested + ";\n") == "STEP: LISTS NESTED TOO DEEPLY");
  // Every length of either file: read, or refused with a reason; nothing else.
  for (std::size_t n = 0; n < iges.size(); n += 7) {
    CAPTURE(n);
    CHECK(!reason_iges(iges.substr(0, n)).empty());
  }
  for (std::size_t n = 0; n < step.size(); n += 7) {
    CAPTURE(n);
    CHECK(!reason_step(step.substr(0, n)).empty());
  }
}

}  // namespace igds::test::exchange
