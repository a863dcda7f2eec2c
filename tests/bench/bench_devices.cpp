// Size and speed of the device streams for a DISPLAY SURFACE of a 200 x 200 grid (ORTHOGONAL
// XY): bytes per vector of the 4013 stream and of the HP-GL plot, against gnuplot's tek40xx and
// hpgl terminals drawing the same grid when gnuplot is installed; pen-up travel of the plot
// order against the drawing order; encoding speed. And the plot order alone on the placed
// polylines of 1000 x 1000 and 2000 x 2000 grids, against the reference it replaced.
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "commands/picture.h"
#include "devices/hpgl.h"
#include "devices/hpgl_plot.h"
#include "devices/plot_order.h"
#include "devices/render.h"
#include "devices/tek4013.h"
#include "devices/tek_stream.h"
#include "tests/bench/bench.h"
#include "tests/devices/plot_order_reference.h"
#include "tests/devices/support.h"

namespace {

constexpr std::size_t side = 200;

// Vectors drawn by an HP-GL stream of gnuplot's kind (PU/PD with or without coordinates,
// PA/PR), counted as coordinate pairs reached with the pen down.
std::size_t hpgl_vectors(const std::string& s) {
  std::size_t vectors = 0;
  bool down = false;
  std::size_t i = 0;
  while (i + 1 < s.size()) {
    if (!std::isupper(static_cast<unsigned char>(s[i])) ||
        !std::isupper(static_cast<unsigned char>(s[i + 1]))) {
      ++i;
      continue;
    }
    std::string op = s.substr(i, 2);
    std::size_t end = s.find_first_of(";\n", i + 2);
    if (end == std::string::npos) end = s.size();
    std::string args = s.substr(i + 2, end - i - 2);
    if (op == "LB") {
      end = s.find('\x03', i);
      if (end == std::string::npos) end = s.size();
      args.clear();
    }
    std::size_t numbers = 0;
    bool in_number = false;
    for (char c : args) {
      bool digit = std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
      if (digit && !in_number) ++numbers;
      in_number = digit;
    }
    if (op == "PU") down = false;
    if (op == "PD") down = true;
    if ((op == "PD" || op == "PA" || op == "PR") && down) vectors += numbers / 2;
    i = end + 1;
  }
  return vectors;
}

// gnuplot drawing the grid with `terminal`; "" when gnuplot is not there or fails.
std::string gnuplot(const std::string& terminal) {
  auto dir = std::filesystem::temp_directory_path() / fmt::format("igds-bench-{}", getpid());
  std::filesystem::create_directories(dir);
  {
    std::ofstream data(dir / "grid.dat");
    for (std::size_t c = 0; c < side; ++c) {
      for (std::size_t r = 0; r < side; ++r) data << r << ' ' << c << " 0\n";
      data << '\n';
    }
  }
  std::string command = fmt::format(
      "cd '{}' && gnuplot -e \"set terminal {}; set output 'out'; set view map; unset border; "
      "unset tics; unset key; splot 'grid.dat' with lines\" >/dev/null 2>&1",
      dir.string(), terminal);
  std::string out;
  if (std::system(command.c_str()) == 0) {
    std::ifstream in(dir / "out", std::ios::binary);
    out.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::filesystem::remove_all(dir);
  return out;
}

std::size_t tek_vectors(const std::string& stream) {
  std::size_t n = 0;
  for (const auto& p : igds::test::devices::decode_tek(stream, 10).paths) n += p.size() - 1;
  return n;
}

}  // namespace

IGDS_BENCH("devices") {
  const igds::Image im = igds::test::devices::flat_grid(side);
  const igds::Picture pic = igds::picture_of(im);

  std::string tek = igds::display_bytes(pic, igds::TermMode::tek, {});
  std::size_t vectors = tek_vectors(tek);
  double tek_per_vector = double(tek.size()) / double(vectors);
  fmt::print("tek_vectors {}\n", vectors);
  fmt::print("tek_bytes_per_vector {:.3f}\n", tek_per_vector);
  std::string g = gnuplot("tek40xx");
  if (!g.empty()) {
    double gp = double(g.size()) / double(tek_vectors(g));
    fmt::print("gnuplot_tek_bytes_per_vector {:.3f}\n", gp);
    fmt::print("tek_bytes_vs_gnuplot {:.3f}\n", tek_per_vector / gp);
  }

  igds::Plot plot = igds::plot_hpgl(pic, {});
  fmt::print("hpgl_vectors {}\n", plot.stats.vectors);
  fmt::print("hpgl_bytes_per_vector {:.3f}\n",
             double(plot.stats.bytes) / double(plot.stats.vectors));
  std::string gh = gnuplot("hpgl");
  if (!gh.empty())
    fmt::print("gnuplot_hpgl_bytes_per_vector {:.3f}\n",
               double(gh.size()) / double(hpgl_vectors(gh)));

  // The same plot in drawing order: the placed polylines sent as they come.
  igds::PlotLayout layout = igds::plot_layout(pic, {});
  igds::DevicePoint lim = igds::hp7475a.limit(igds::Paper::a4);
  igds::Placed placed = igds::place(pic.drawing, layout.at, {0, 0, double(lim.x), double(lim.y)},
                                    {.point = igds::plot_point_mm / igds::hp7475a.unit_mm});
  igds::StringOut naive_plot;
  igds::HpglEncoder naive(igds::hp7475a, false, naive_plot);
  igds::DevicePoint t = layout.text;
  for (const auto& line : pic.caption) {
    naive.text(t, line);
    t.y -= static_cast<int>(std::lround(layout.line));
  }
  for (std::size_t k = 0; k < placed.paths.size(); ++k) naive.polyline(placed.paths[k]);
  naive.finish();
  fmt::print("hpgl_pen_up_mm_ordered {:.0f}\n", plot.stats.pen_up_mm);
  fmt::print("hpgl_pen_up_mm_drawing_order {:.0f}\n", naive.stats().pen_up_mm);
  fmt::print("hpgl_pen_lifts {}\n", plot.stats.pen_lifts);

  // Encoding speed: the 4013 encoder alone on the placed polylines, then the whole DISPLAY
  // (picture, placement, clipping, encoding), per byte sent.
  igds::Placed on_screen = igds::place(pic.drawing, igds::fit(pic.drawing, {16, 16, 751, 751}, 3),
                                       {0, 0, 1023, 779}, {});
  std::size_t bytes = 0;
  double e = igds::bench::best_seconds(10, [&] {
    igds::TekEncoder encoder;
    for (std::size_t k = 0; k < on_screen.paths.size(); ++k) encoder.polyline(on_screen.paths[k]);
    bytes = encoder.bytes().size();
  });
  fmt::print("tek_encode_mb_per_s {:.1f}\n", double(bytes) / e / 1e6);
  double s = igds::bench::best_seconds(
      10, [&] { bytes = igds::tek_stream(igds::picture_of(im), {}).size(); });
  fmt::print("tek_display_mb_per_s {:.1f}\n", double(bytes) / s / 1e6);
  double p = igds::bench::best_seconds(
      3, [&] { bytes = igds::plot_hpgl(igds::picture_of(im), {}).hpgl.size(); });
  fmt::print("hpgl_plot_ms {:.1f}\n", p * 1e3);
}

IGDS_BENCH("plot_order") {
  double ms[2] = {0, 0};
  std::size_t segments[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const std::size_t n = 1000 * (k + 1);
    // The polylines PLOT orders: curves then stringers, placed on A4 in plotter units.
    igds::Picture pic = igds::picture_of(igds::test::devices::flat_grid(n));
    igds::PlotLayout layout = igds::plot_layout(pic, {});
    igds::DevicePoint lim = igds::hp7475a.limit(igds::Paper::a4);
    const igds::Placed styled =
        igds::place(pic.drawing, layout.at, {0, 0, double(lim.x), double(lim.y)},
                    {.point = igds::plot_point_mm / igds::hp7475a.unit_mm});
    std::vector<igds::DevicePath> paths;
    for (std::size_t j = 0; j < styled.paths.size(); ++j)
      paths.emplace_back(styled.paths[j].begin(), styled.paths[j].end());
    pic = {};
    for (const auto& p : paths) segments[k] += p.size() - 1;
    // A fresh output each time, as PLOT has.
    igds::PathList ordered;
    ms[k] = 1e3 * igds::bench::best_seconds(3, [&] {
              ordered = {};
              igds::plot_order(paths, {0, 0}, ordered);
            });
    std::vector<igds::DevicePath> reference;
    double ref = 1e3 * igds::bench::best_seconds(1, [&] {
                   reference = igds::test::reference::plot_order(paths, {0, 0});
                 });
    bool same = reference.size() == ordered.size();
    for (std::size_t i = 0; same && i < ordered.size(); ++i)
      same = std::equal(reference[i].begin(), reference[i].end(), ordered[i].begin(),
                        ordered[i].end());
    fmt::print("plot_order_{0}x{0}_segments {1}\n", n, segments[k]);
    fmt::print("plot_order_{0}x{0}_ms {1:.1f}\n", n, ms[k]);
    fmt::print("plot_order_{0}x{0}_reference_ms {1:.1f}\n", n, ref);
    fmt::print("plot_order_{0}x{0}_same_as_reference {1}\n", n, same ? 1 : 0);
  }
  // The whole PLOT of the 2000 x 2000 grid: picture, placement, clipping, order, HP-GL.
  const igds::Image im = igds::test::devices::flat_grid(2000);
  std::size_t bytes = 0;
  double plot = igds::bench::best_seconds(
      2, [&] { bytes = igds::plot_hpgl(igds::picture_of(im), {}).hpgl.size(); });
  fmt::print("hpgl_plot_2000x2000_ms {:.1f}\n", plot * 1e3);
  fmt::print("hpgl_plot_2000x2000_mb_per_s {:.1f}\n", double(bytes) / plot / 1e6);
  // 1.0 when the time grows as the number of segments does.
  fmt::print("plot_order_time_growth_per_segment_growth {:.2f}\n",
             (ms[1] / ms[0]) / (double(segments[1]) / double(segments[0])));
}
