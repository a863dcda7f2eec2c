// Speed of the exchange files for the 500 x 500 surface of the "grid" benchmark: the DUCT picture
// (with INTCU = INTST = 1: 999 curves and 999 stringers of Bézier spans, three million pixels,
// within the reader's four million) written and read back, IGES and STEP written. MB/s counts
// the file's bytes.
#include <fmt/core.h>

#include <cmath>
#include <string>

#include "tests/bench/bench.h"
#include "tests/bench/inputs.h"
#include "workspace/exchange/duct.h"
#include "workspace/exchange/iges.h"
#include "workspace/exchange/step.h"
#include "workspace/exchange/surface_curves.h"
#include "workspace/kernels/surface.h"

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

}  // namespace

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
}
