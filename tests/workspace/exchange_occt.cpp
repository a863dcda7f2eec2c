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

#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

#include "tests/support/skip.h"
#include "tests/workspace/exchange_support.h"
#include "workspace/exchange/iges.h"
#include "workspace/exchange/step.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/fit.h"

namespace igds::test::exchange {

namespace {

namespace fs = std::filesystem;

struct Draw {
  std::string program;
  std::map<std::string, std::string> env;
};

// The DRAW program, and a library path where the plugins `pload` opens by their unversioned
// names can be found (Debian ships only libTK*.so.7 without its -dev packages).
std::optional<Draw> find_draw(const fs::path& scratch) {
  Draw d;
  for (const char* name : {"DRAWEXE", "occt-draw-7.6", "occt-draw"}) {
    if (have_program(name)) {
      d.program = name;
      break;
    }
  }
  if (d.program.empty()) return std::nullopt;
  const fs::path libs = scratch / "lib";
  fs::create_directories(libs);
  for (const char* plugin : {"libTKTopTest", "libTKXSDRAW"}) {
    for (const char* dir : {"/usr/lib/x86_64-linux-gnu", "/usr/lib/aarch64-linux-gnu", "/usr/lib64",
                            "/usr/lib", "/usr/local/lib"}) {
      std::error_code ec;
      if (fs::exists(fs::path(dir) / (std::string(plugin) + ".so"), ec)) break;
      bool linked = false;
      for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string file = entry.path().filename().string();
        if (file.rfind(std::string(plugin) + ".so.", 0) == 0) {
          fs::create_symlink(entry.path(), libs / (std::string(plugin) + ".so"), ec);
          linked = true;
          break;
        }
      }
      if (linked) break;
    }
  }
  const char* old = std::getenv("LD_LIBRARY_PATH");
  d.env["LD_LIBRARY_PATH"] = libs.string() + (old && *old ? std::string(":") + old : "");
  return d;
}

// One evaluation: a surface (face number f, 1-based) at (u, v), or a curve (edge e) at t.
struct Probe {
  bool surface = true;
  std::size_t item = 0;
  double u = 0, v = 0;
  Vec3 expected;
};

struct Result {
  std::string transfer_checks, model_checks, shape_check, counts;
  std::vector<Vec3> values;
  std::string all;
};

// Reads `file` with igesread or stepread, then evaluates the probes on the sub-shapes of the
// result in order (faces, then edges, as the file lists its entities).
Result run_draw(const Draw& draw, const fs::path& dir, const fs::path& file, bool step,
                const std::vector<Probe>& probes) {
  std::string tcl = "pload MODELING DATAEXCHANGEKERNEL\n";
  if (step)
    tcl += fmt::format("set read [stepread {{{}}} r *]\nrenamevar r_1 shape\n", file.string());
  else
    tcl += fmt::format("set read [igesread {{{}}} shape *]\n", file.string());
  tcl +=
      "puts \"READ-BEGIN\\n$read\\nREAD-END\"\n"
      "puts \"TRANSFER-BEGIN\\n[tpstat c]\\nTRANSFER-END\"\n"
      "puts \"MODEL-BEGIN\\n[data c]\\nMODEL-END\"\n"
      "puts \"SHAPE-BEGIN\\n[checkshape shape]\\nSHAPE-END\"\n"
      "puts \"COUNT-BEGIN\\n[nbshapes shape]\\nCOUNT-END\"\n"
      "explode shape\n"
      "set probes {\n";
  for (const Probe& p : probes)
    tcl += fmt::format("{{{} {} {:.17g} {:.17g}}}\n", p.surface ? "s" : "c", p.item, p.u, p.v);
  tcl +=
      "}\n"
      "foreach p $probes {\n"
      "  lassign $p kind k u v\n"
      "  if {![info exists made($kind$k)]} {\n"
      "    if {$kind == \"s\"} { mksurface g$kind$k shape_$k } else { mkcurve g$kind$k shape_$k }\n"
      "    set made($kind$k) 1\n"
      "  }\n"
      "  if {$kind == \"s\"} { svalue g$kind$k $u $v x y z } else { cvalue g$kind$k $u x y z }\n"
      "  puts \"VALUE [dval x] [dval y] [dval z]\"\n"
      "}\n"
      "exit\n";
  const fs::path script = dir / (step ? "check_step.tcl" : "check_iges.tcl");
  write_file(script, tcl);
  RunOptions options;
  options.env = draw.env;
  options.cwd = dir;
  options.timeout_seconds = 600;
  const RunResult run = igds::test::run({draw.program, "-b", "-f", script.string()}, options);
  Result r;
  r.all = run.out + run.err;
  auto between = [&](const std::string& begin, const std::string& end) {
    const std::size_t a = run.out.find(begin + "\n"), b = run.out.find("\n" + end);
    return a == std::string::npos || b == std::string::npos || b < a
               ? std::string()
               : run.out.substr(a + begin.size() + 1, b - a - begin.size() - 1);
  };
  r.transfer_checks = between("TRANSFER-BEGIN", "TRANSFER-END");
  r.model_checks = between("MODEL-BEGIN", "MODEL-END");
  r.shape_check = between("SHAPE-BEGIN", "SHAPE-END");
  r.counts = between("COUNT-BEGIN", "COUNT-END");
  std::istringstream lines(run.out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("VALUE ", 0) != 0) continue;
    std::istringstream values(line.substr(6));
    Vec3 v;
    values >> v.x >> v.y >> v.z;
    r.values.push_back(values ? v : Vec3{NAN, NAN, NAN});
  }
  return r;
}

// Probes at INTPN points (every `step`th) on the faces of the patches (or the one surface), and
// at the input points on the curves and stringers, edges numbered after the faces.
std::vector<Probe> probes_of(const TestSurface& t, SurfaceForm form, std::size_t step) {
  const auto& in = t.input;
  const std::size_t nc = in.nocur, ns = in.nostr, ic = in.intcu, is = in.intst;
  const GridShape g = intpn_shape(in.nocur, in.nostr, in.intcu, in.intst);
  std::vector<Probe> probes;
  for (std::size_t k = 0; k < g.rows * g.cols; k += step) {
    const std::size_t row = k / g.cols, col = k % g.cols;
    const std::size_t i = std::min(row / (ic + 1), nc - 2), j = std::min(col / (is + 1), ns - 2);
    Probe p;
    p.item = form == SurfaceForm::one ? 1 : i * (ns - 1) + j + 1;
    p.u = double(j) + double(col - j * (is + 1)) / double(is + 1);
    p.v = double(i) + double(row - i * (ic + 1)) / double(ic + 1);
    p.expected = Vec3::load(t.surface.intpn.data() + 3 * k);
    probes.push_back(p);
  }
  const std::size_t faces = form == SurfaceForm::one ? 1 : (nc - 1) * (ns - 1);
  for (std::size_t i = 0; i < nc; ++i) {
    double t_k = 0;
    for (std::size_t j = 0; j < ns; ++j) {
      const Vec3 p = Vec3::load(t.inppn.data() + 3 * (i * ns + j));
      if (j > 0) t_k += norm(p - Vec3::load(t.inppn.data() + 3 * (i * ns + j - 1)));
      probes.push_back({false, faces + i + 1, t_k, 0, p});
    }
  }
  for (std::size_t j = 0; j < ns; ++j) {
    double t_k = 0;
    for (std::size_t i = 0; i < nc; ++i) {
      const Vec3 p = Vec3::load(t.inppn.data() + 3 * (i * ns + j));
      if (i > 0) t_k += norm(p - Vec3::load(t.inppn.data() + 3 * ((i - 1) * ns + j)));
      probes.push_back({false, faces + nc + j + 1, t_k, 0, p});
    }
  }
  return probes;
}

// The largest error of the probes, relative to the largest coordinate of INTPN.
double worst_error(const TestSurface& t, const std::vector<Probe>& probes, const Result& r) {
  REQUIRE(r.values.size() == probes.size());
  double worst = 0;
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const double e = norm(r.values[k] - probes[k].expected);
    worst = std::max(worst, std::isfinite(e) ? e : INFINITY);
  }
  return worst / largest_coordinate(t.surface.intpn);
}

bool no_messages(const std::string& checks) {
  return checks.find("Nb Total:0  for 0 items") != std::string::npos;
}

}  // namespace

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
        const std::size_t faces =
            form == SurfaceForm::one
                ? 1
                : std::size_t(c.surface.input.nocur - 1) * std::size_t(c.surface.input.nostr - 1);
        CHECK(r.counts.find(fmt::format("FACE      : {}\n", faces)) != std::string::npos);
        CHECK(worst <= 1e-9);
      }
    }
  }
}

}  // namespace igds::test::exchange
