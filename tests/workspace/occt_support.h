// OpenCASCADE's DRAW test harness as a reader of igds's IGES and STEP files (Debian's occt-draw,
// DRAWEXE elsewhere; scripts/setup --test installs it): finding it, running a check script on a
// file, and the probes where igds knows the answer. Shared by tests/workspace/exchange_occt.cpp
// and the end-to-end EXPORT IGES test (tests/e2e/exchange_commands.cpp).
#pragma once

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/process.h"
#include "tests/workspace/exchange_support.h"
#include "workspace/exchange/iges.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/fit.h"

namespace igds::test::exchange {

namespace fs = std::filesystem;

struct Draw {
  std::string program;
  std::map<std::string, std::string> env;
};

// The DRAW program, and a library path where the plugins `pload` opens by their unversioned
// names can be found (Debian ships only libTK*.so.7 without its -dev packages).
inline std::optional<Draw> find_draw(const fs::path& scratch) {
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

// One evaluation: a surface (face number f, 1-based) at (u, v), or a curve (edge e of the curves'
// group) at t.
struct Probe {
  bool surface = true;
  std::size_t item = 0;
  double u = 0, v = 0;
  Vec3 expected;
};

struct Result {
  std::string transfer_checks, model_checks, shape_check, counts;
  std::string free_counts;  // nbshapes of the free boundary
  std::vector<Vec3> values;
  std::string all;
};

// Reads `file` with igesread or stepread, then evaluates the probes on the faces of the result in
// order, and on the edges of its last part, the group of the input curves, in order.
inline Result run_draw(const Draw& draw, const fs::path& dir, const fs::path& file, bool step,
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
      // The free boundary: edges that only one face uses (shape_c, its compound of wires).
      "freebounds shape 1e-7\n"
      "puts \"FREE-BEGIN\\n[nbshapes shape_c]\\nFREE-END\"\n"
      // The faces in order; the curves' group is the result's last part, its edges in order.
      "explode shape F\n"
      "copy shape top\n"
      "set parts [explode top]\n"
      "set curves [explode [lindex $parts end] E]\n"
      "set probes {\n";
  for (const Probe& p : probes)
    tcl += fmt::format("{{{} {} {:.17g} {:.17g}}}\n", p.surface ? "s" : "c", p.item, p.u, p.v);
  tcl +=
      "}\n"
      "foreach p $probes {\n"
      "  lassign $p kind k u v\n"
      "  if {![info exists made($kind$k)]} {\n"
      "    if {$kind == \"s\"} { mksurface g$kind$k shape_$k } else {\n"
      "      mkcurve g$kind$k [lindex $curves [expr {$k - 1}]] }\n"
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
  r.free_counts = between("FREE-BEGIN", "FREE-END");
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
// at the input points on the curves and stringers, edges of the curves' group (a pole is not one).
inline std::vector<Probe> probes_of(const TestSurface& t, SurfaceForm form, std::size_t step) {
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
  // The curves and stringers in the file's order, a pole (all its points one point) left out.
  std::size_t edge = 0;
  auto line = [&](std::size_t count, auto point) {
    bool pole = true;
    for (std::size_t m = 1; m < count; ++m) pole = pole && point(m) == point(0);
    if (pole) return;
    ++edge;
    double t_k = 0;
    for (std::size_t m = 0; m < count; ++m) {
      if (m > 0) t_k += norm(point(m) - point(m - 1));
      probes.push_back({false, edge, t_k, 0, point(m)});
    }
  };
  for (std::size_t i = 0; i < nc; ++i)
    line(ns, [&](std::size_t j) { return Vec3::load(t.inppn.data() + 3 * (i * ns + j)); });
  for (std::size_t j = 0; j < ns; ++j)
    line(nc, [&](std::size_t i) { return Vec3::load(t.inppn.data() + 3 * (i * ns + j)); });
  return probes;
}

// The largest error of the probes, relative to the largest coordinate of INTPN.
inline double worst_error(const TestSurface& t, const std::vector<Probe>& probes, const Result& r) {
  REQUIRE(r.values.size() == probes.size());
  double worst = 0;
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const double e = norm(r.values[k] - probes[k].expected);
    worst = std::max(worst, std::isfinite(e) ? e : INFINITY);
  }
  return worst / largest_coordinate(t.surface.intpn);
}

// The number nbshapes gives for `kind` ("FACE", "SHELL", "EDGE") in `counts`; -1 when absent.
inline long shape_count(const std::string& counts, const std::string& kind) {
  const std::size_t at = counts.find(" " + kind + " ");
  if (at == std::string::npos) return -1;
  const std::size_t colon = counts.find(':', at);
  return colon == std::string::npos ? -1 : std::strtol(counts.c_str() + colon + 1, nullptr, 10);
}

// What OpenCASCADE must have made of a file of `t`: one face, or (FACES) one shell of a face per
// patch whose free boundary is the grid's border alone (no edge inside used by one face only).
inline void check_topology(const TestSurface& t, SurfaceForm form, const Result& r) {
  const long nc = t.input.nocur, ns = t.input.nostr;
  if (form == SurfaceForm::one) {
    CHECK(shape_count(r.counts, "FACE") == 1);
    CHECK(shape_count(r.counts, "SHELL") == 0);
  } else {
    CHECK(shape_count(r.counts, "FACE") == (nc - 1) * (ns - 1));
    CHECK(shape_count(r.counts, "SHELL") == 1);
  }
  // The border: NOSTR-1 edges along each of the first and last curves, NOCUR-1 up each of the
  // first and last stringers, but those along a pole; for the one surface, its face's sides but
  // a pole.
  const BezierNet net = surface_net(t.input, t.surface.patches);
  const PatchShell shell(net, std::size_t(nc), std::size_t(ns));
  long border = 0, sides = 0;
  for (std::size_t i : {std::size_t(0), std::size_t(nc - 1)}) {
    long kept = 0;
    for (std::size_t j = 0; j + 1 < std::size_t(ns); ++j) kept += !shell.degenerate(true, i, j);
    border += kept;
    sides += kept > 0;
  }
  for (std::size_t j : {std::size_t(0), std::size_t(ns - 1)}) {
    long kept = 0;
    for (std::size_t i = 0; i + 1 < std::size_t(nc); ++i) kept += !shell.degenerate(false, i, j);
    border += kept;
    sides += kept > 0;
  }
  CHECK(shape_count(r.free_counts, "EDGE") == (form == SurfaceForm::one ? sides : border));
}

inline bool no_messages(const std::string& checks) {
  return checks.find("Nb Total:0  for 0 items") != std::string::npos;
}

}  // namespace igds::test::exchange
