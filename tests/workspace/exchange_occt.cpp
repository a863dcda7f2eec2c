// The IGES and STEP files checked by a reader igds did not write: OpenCASCADE's DRAW test harness
// (Debian's occt-draw, DRAWEXE elsewhere; scripts/setup --test installs it). It reads each file
// (igesread, stepread), reports the translator's messages and the model's checks (tpstat c,
// data c), checks the shape (checkshape), and evaluates the surfaces (svalue) and curves (cvalue)
// at parameters where igds knows the answer: every INTPN point of a small surface, a sampling of
// a bigger one, and the input points on the curves and stringers.
//
// Without the program the test is skipped (tests/support/skip.h).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include "tests/support/skip.h"
#include "tests/workspace/exchange_support.h"
#include "tests/workspace/occt_support.h"
#include "workspace/exchange/iges.h"
#include "workspace/exchange/step.h"

namespace igds::test::exchange {

TEST_CASE("OpenCASCADE reads the IGES and STEP files without a message and finds the surface") {
  TempDir dir;
  const auto draw = find_draw(dir.path());
  IGDS_SKIP_UNLESS(draw.has_value(),
                   "OpenCASCADE's DRAW (occt-draw or DRAWEXE) is not installed: scripts/setup "
                   "--test installs it");
  struct Case {
    const char* name;
    TestSurface surface;
    std::size_t step;
  };
  std::vector<Case> cases;
  cases.push_back({"small", golden_surface(), 1});
  cases.push_back({"bigger", test_surface(25, 20, 2, 2), 7});
  // A pole: the first curve's points all one point, its edges left out of the shell.
  TestSurface pole = test_surface(4, 5, 1, 1);
  for (int j = 0; j < 5; ++j) std::fill_n(pole.inppn.data() + 3 * j, 3, 1.0);
  pole.surface = interpolate(pole.input);
  cases.push_back({"pole", std::move(pole), 1});
  for (auto& c : cases) {
    const CadHeader header{"CHECK", "CHECK.IGS", {1987, 9, 22, 9, 55, 50}, "", ""};
    for (SurfaceForm form : {SurfaceForm::patches, SurfaceForm::one}) {
      for (bool step : {false, true}) {
        const std::string what = fmt::format("{} surface, {} {}", c.name,
                                             form == SurfaceForm::one ? "one surface" : "patches",
                                             step ? "STEP" : "IGES");
        CAPTURE(what);
        const fs::path file = dir.path() / (step ? "check.stp" : "check.igs");
        write_file(file,
                   step ? write_step(c.surface.input, c.surface.surface.patches, header, form)
                        : write_iges(c.surface.input, c.surface.surface.patches, header, form));
        const std::vector<Probe> probes = probes_of(c.surface, form, c.step);
        const Result r = run_draw(*draw, dir.path(), file, step, probes);
        const double worst = worst_error(c.surface, probes, r);
        MESSAGE(fmt::format("{}: {} probes, largest relative error {:.2e}", what, probes.size(),
                            worst));
        INFO(r.all.substr(0, 4000));
        // IGES's one surface is C0 across its patch borders, which the reader says (iges.h).
        if (!step && form == SurfaceForm::one) {
          CHECK(r.transfer_checks.find("Nb Total:1  for 1 items") != std::string::npos);
          CHECK(r.transfer_checks.find("Resulting Geom_Surface is C0-continuous") !=
                std::string::npos);
        } else {
          CHECK(no_messages(r.transfer_checks));
        }
        CHECK(no_messages(r.model_checks));
        CHECK(r.shape_check.find("This shape seems to be valid") != std::string::npos);
        check_topology(c.surface, form, r);
        CHECK(worst <= 1e-9);
      }
    }
  }
}

TEST_CASE("OpenCASCADE reads each unit as declared, and says when there is none") {
  TempDir dir;
  const auto draw = find_draw(dir.path());
  IGDS_SKIP_UNLESS(draw.has_value(),
                   "OpenCASCADE's DRAW (occt-draw or DRAWEXE) is not installed: scripts/setup "
                   "--test installs it");
  const TestSurface t = golden_surface();
  // OpenCASCADE gives its shapes in millimetres; NONE is read as millimetres, with a remark.
  const struct {
    LengthUnit unit;
    double millimetres;
  } units[] = {{LengthUnit::mm, 1},      {LengthUnit::cm, 10},      {LengthUnit::m, 1000},
               {LengthUnit::inch, 25.4}, {LengthUnit::foot, 304.8}, {LengthUnit::none, 1}};
  for (const auto& u : units) {
    CadHeader header{"CHECK", "CHECK.IGS", {1987, 9, 22, 9, 55, 50}, "", "", u.unit};
    for (bool step : {false, true}) {
      CAPTURE(u.millimetres);
      CAPTURE(step);
      const fs::path file = dir.path() / (step ? "check.stp" : "check.igs");
      write_file(file, step ? write_step(t.input, t.surface.patches, header)
                            : write_iges(t.input, t.surface.patches, header));
      std::vector<Probe> probes = probes_of(t, SurfaceForm::one, 1);
      const Result r = run_draw(*draw, dir.path(), file, step, probes);
      INFO(r.all.substr(0, 4000));
      REQUIRE(r.values.size() == probes.size());
      double worst = 0;
      for (std::size_t k = 0; k < probes.size(); ++k)
        worst = std::max(worst, norm(r.values[k] - u.millimetres * probes[k].expected));
      CHECK(worst <= 1e-9 * u.millimetres * largest_coordinate(t.surface.intpn));
      const bool none = u.unit == LengthUnit::none;
      if (step) {
        CHECK((r.transfer_checks.find("No Length Uncertainty") != std::string::npos) == none);
        CHECK(no_messages(r.model_checks));
      } else {
        CHECK((r.model_checks.find("Unit Name parameter is not recognized") != std::string::npos) ==
              none);
      }
    }
  }
}

}  // namespace igds::test::exchange
