// Speed of the exchange files for the 500 x 500 surface of the "grid" benchmark: the DUCT picture
// (with INTCU = INTST = 1: 999 curves and 999 stringers of Bézier spans, three million pixels,
// within the reader's four million) written and read back, IGES and STEP written. MB/s counts
// the file's bytes. Then the commands themselves, files written to a scratch disk: EXPORT DUCT,
// EXPORT IGES and DISPLAY PICTURE of that file. "exchange_4m": every command that writes a user
// file (EXPORT DUCT, IGES, STEP, SVG and WRITE) on a surface of four million points, the median of
// five runs of the whole command. "exchange_cad": EXPORT IGES and STEP alone on that surface (the
// median of three runs each), to profile them.
#include <fmt/core.h>

#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/context.h"
#include "tests/bench/bench.h"
#include "tests/bench/inputs.h"
#include "workspace/exchange/duct.h"
#include "workspace/exchange/iges.h"
#include "workspace/exchange/step.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/journal.h"
#include "workspace/kernels/surface.h"

namespace igds {
extern const Command export_command;
extern const Command display_command;
extern const Command write_command;
}  // namespace igds

namespace {

using igds::bench::Input;
using igds::bench::wavy;

using igds::Array;

void report(const char* name, double seconds, std::size_t bytes) {
  fmt::print("{}_ms {:.1f}\n", name, seconds * 1e3);
  if (bytes > 0) {
    fmt::print("{}_mb {:.1f}\n", name, double(bytes) / 1e6);
    fmt::print("{}_mb_per_s {:.1f}\n", name, double(bytes) / 1e6 / seconds);
  }
}

// A Context that answers from the command line only and shows nothing: the command's own work.
class QuietContext final : public igds::Context {
 public:
  QuietContext(std::filesystem::path dir, igds::Workspace ws) : ws_(std::move(ws)), disk_(dir) {}
  void run(const igds::Command& command, std::string_view option, std::vector<std::string> words) {
    pending_ = std::move(words);
    command.run(*this, igds::choose(command.options, option));
  }
  igds::Workspace& workspace() override { return ws_; }
  const igds::Options& options() const override { return options_; }
  const igds::Disk& disk() const override { return disk_; }
  std::span<const std::string_view> ask_words(const igds::Prompt&) override {
    if (pending_.empty()) throw igds::EndOfInput{};
    return reply_.of(std::exchange(pending_, {}));
  }
  void unread(std::vector<std::string> words) override {
    words.insert(words.end(), pending_.begin(), pending_.end());
    pending_ = std::move(words);
  }
  bool has_pending() const override { return !pending_.empty(); }
  bool pending_from_command_line() const override { return !pending_.empty(); }
  void say(std::string_view) override {}
  void document(std::string_view) override {}
  void report(std::string_view) override {}
  void show(const igds::ImageRef&) override {}
  std::optional<igds::PickedAddress> pick(const igds::Prompt&) override { return std::nullopt; }
  igds::Journal& journal() override { return journal_; }
  void erase() override {}
  void send_to_terminal(std::string_view) override {}
  void end_session(bool) override {}

 private:
  igds::Workspace ws_;
  igds::Options options_;
  igds::Disk disk_;
  igds::Journal journal_{ws_};
  igds::Reply reply_;
  std::vector<std::string> pending_;
};

// A workspace holding the input grid and its surface, interpolated with `density` curves and
// stringers between the input ones.
igds::Workspace workspace_of(const Input& in, int density, igds::Surface surface) {
  igds::Workspace ws;
  ws.nocur = in.nocur;
  ws.nostr = in.nostr;
  ws.intcu = ws.intst = density;
  ws.inppn = in.inppn;
  ws.inptg = in.inptg;
  ws.patches = std::move(surface.patches);
  ws.intpn = std::move(surface.intpn);
  return ws;
}

// The commands on the surface, through the disk (files written crash-safely, fsync'd).
void bench_commands(const Input& in, const igds::Surface& surface) {
  char scratch[] = "/tmp/igds-bench-exchange-XXXXXX";
  if (!mkdtemp(scratch)) return;
  const std::filesystem::path dir = scratch;
  QuietContext ctx(dir, workspace_of(in, 1, surface));
  const double duct =
      igds::bench::best_seconds(3, [&] { ctx.run(igds::export_command, "DUCT", {"GRID"}); });
  report("command_export_duct_500x500_int1", duct,
         std::filesystem::file_size(dir / "GRID.DUCTPIC"));
  const double iges =
      igds::bench::best_seconds(3, [&] { ctx.run(igds::export_command, "IGES", {"GRID"}); });
  report("command_export_iges_500x500", iges, std::filesystem::file_size(dir / "GRID.IGS"));
  const double picture = igds::bench::best_seconds(3, [&] {
    ctx.run(igds::display_command, "PICTURE", {"GRID", "ASSONOMETRIC", "110", "130", "120"});
  });
  report("command_display_picture_500x500_int1", picture,
         std::filesystem::file_size(dir / "GRID.DUCTPIC"));
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

// Seconds taken by the median of `repeats` runs of `f`.
template <class F>
double median_seconds(int repeats, F&& f) {
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) times.push_back(igds::bench::best_seconds(1, f));
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

// The 500 x 500 input grid with INTCU = INTST = 3: INTPN of 1498 x 1498 points, the DUCT picture
// of its 2996 curves and stringers, 249001 patches for IGES and STEP. The figures count the whole
// command, files written crash-safely into a scratch disk and fsync'd.
IGDS_BENCH("exchange_4m") {
  const Input in = wavy(500, 500);
  igds::Workspace ws =
      workspace_of(in, 3, igds::interpolate({in.nocur, in.nostr, 3, 3, &in.inppn, &in.inptg}));
  char scratch[] = "/tmp/igds-bench-exchange-XXXXXX";
  if (!mkdtemp(scratch)) return;
  const std::filesystem::path dir = scratch;
  {
    QuietContext ctx(dir, std::move(ws));
    ctx.run(igds::display_command, "SURFACE", {"ASSONOMETRIC", "110", "130", "120"});
    struct Case {
      const char* key;
      const igds::Command& command;
      const char* option;
      const char* file;
    };
    const Case cases[] = {
        {"export_duct_4m", igds::export_command, "DUCT", "X.DUCTPIC"},
        {"export_iges_4m", igds::export_command, "IGES", "X.IGS"},
        {"export_step_4m", igds::export_command, "STEP", "X.STP"},
        {"export_svg_4m", igds::export_command, "SVG", "X.SVG"},
        {"write_4m", igds::write_command, "", "X.IGDSCHAR"},
    };
    for (const Case& c : cases) {
      const double seconds = median_seconds(5, [&] { ctx.run(c.command, c.option, {"X"}); });
      report(c.key, seconds, std::filesystem::file_size(dir / c.file));
      std::filesystem::remove(dir / c.file);
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

// EXPORT IGES and STEP of the 500 x 500 grid's 249001 patches, files written crash-safely into a
// scratch disk (in TMPDIR, or /tmp) and fsync'd: the median of three runs of each command.
IGDS_BENCH("exchange_cad") {
  const Input in = wavy(500, 500);
  const igds::SurfaceInput si{in.nocur, in.nostr, 3, 3, &in.inppn, &in.inptg};
  std::string scratch =
      (std::filesystem::temp_directory_path() / "igds-bench-exchange-XXXXXX").string();
  if (!mkdtemp(scratch.data())) return;
  const std::filesystem::path dir = scratch.c_str();
  {
    QuietContext ctx(dir, workspace_of(in, 3, igds::interpolate(si)));
    for (const char* option : {"IGES", "STEP"}) {
      const std::string file = fmt::format("X.{}", option[0] == 'I' ? "IGS" : "STP");
      const double seconds =
          median_seconds(3, [&] { ctx.run(igds::export_command, option, {"X"}); });
      report(fmt::format("cad_export_{}_500x500", option[0] == 'I' ? "iges" : "step").c_str(),
             seconds, std::filesystem::file_size(dir / file));
      std::filesystem::remove(dir / file);
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

IGDS_BENCH("exchange") {
  const Input in = wavy(500, 500);
  const igds::SurfaceInput si{in.nocur, in.nostr, 1, 1, &in.inppn, &in.inptg};
  const igds::Surface surface = igds::interpolate(si);
  const igds::DuctHeader header{"GRID", "22 SEP 1987 09:55:50", "GRID 500 X 500"};

  // EXPORT DUCT: the drawing, the picture, the text.
  igds::Drawing3 drawing;
  const double curves =
      igds::bench::best_seconds(3, [&] { drawing = igds::surface_curves(si, surface); });
  igds::DuctPicture picture;
  const double convert =
      igds::bench::best_seconds(3, [&] { picture = igds::duct_picture(drawing, header); });
  std::string text;
  const double write = igds::bench::best_seconds(3, [&] { text = igds::write_duct(picture); });
  fmt::print("duct_500x500_int1_pixels {}\n", picture.pixel_count());
  report("duct_500x500_int1_curves", curves, 0);
  report("duct_500x500_int1_picture", convert, 0);
  report("duct_500x500_int1_write", write, text.size());
  report("duct_500x500_int1_export", curves + convert + write, text.size());
  // DISPLAY PICTURE's first steps: the text read and drawn.
  igds::DuctPicture back;
  const double read = igds::bench::best_seconds(3, [&] { back = igds::read_duct(text); });
  report("duct_500x500_int1_read", read, text.size());
  const double draw = igds::bench::best_seconds(3, [&] { drawing = igds::duct_drawing(back); });
  report("duct_500x500_int1_drawing", draw, 0);
  text = std::string();

  // EXPORT IGES and STEP: 249001 patches (or one surface) and 1000 curves.
  const igds::CadHeader cad{"GRID", "GRID.IGS", {1987, 9, 22, 9, 55, 50}, "", ""};
  for (igds::SurfaceForm form : {igds::SurfaceForm::patches, igds::SurfaceForm::one}) {
    const char* suffix = form == igds::SurfaceForm::one ? "one" : "patches";
    const double iges = igds::bench::best_seconds(
        3, [&] { text = igds::write_iges(si, surface.patches, cad, form); });
    report(fmt::format("iges_500x500_{}", suffix).c_str(), iges, text.size());
    text = std::string();
    const double step = igds::bench::best_seconds(
        3, [&] { text = igds::write_step(si, surface.patches, cad, form); });
    report(fmt::format("step_500x500_{}", suffix).c_str(), step, text.size());
    text = std::string();
  }

  bench_commands(in, surface);
}
