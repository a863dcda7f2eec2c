// Golden device streams (tests/golden): byte for byte. IGDS_UPDATE_GOLDEN=1 rewrites them and
// prints what changed.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>

#include "devices/plot.h"
#include "devices/terminal.h"
#include "tests/devices/support.h"
#include "tests/support/process.h"

namespace igds::test::devices {

namespace {

// Where two byte strings first differ, and their sizes.
std::string difference(const std::string& was, const std::string& now) {
  std::size_t i = 0;
  while (i < was.size() && i < now.size() && was[i] == now[i]) ++i;
  if (i == was.size() && i == now.size()) return "unchanged";
  return fmt::format("{} -> {} bytes, first difference at byte {}", was.size(), now.size(), i);
}

void check_golden(const std::string& name, const std::string& bytes) {
  std::filesystem::path path = std::filesystem::path(IGDS_GOLDEN_DIR) / name;
  const char* update = std::getenv("IGDS_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    std::string was = std::filesystem::exists(path) ? read_file(path) : "";
    write_file(path, bytes);
    MESSAGE(fmt::format("golden {}: {}", name, difference(was, bytes)));
    return;
  }
  INFO("golden file " << path.string() << " (IGDS_UPDATE_GOLDEN=1 rewrites it)");
  REQUIRE(std::filesystem::exists(path));
  std::string expected = read_file(path);
  INFO(difference(expected, bytes));
  CHECK(expected == bytes);
}

}  // namespace

// The golden images: small, one of each kind.
Image golden_input() {
  return input_image(3, 4);
}
Image golden_surface() {
  return surface_image(5, 4);
}

TEST_CASE("golden: Tektronix 4013 and 4014 streams") {
  check_golden("input_3x4.tek", tek_stream(golden_input(), {}));
  check_golden("surface_5x4.tek", tek_stream(golden_surface(), {}));
  check_golden("surface_5x4_4014.tek", tek_stream(golden_surface(), {12}));
  check_golden("erase.tek", erase_bytes(TermMode::tek, {}));
}

TEST_CASE("golden: HP-GL plots") {
  check_golden("input_3x4.hpgl", plot_hpgl(golden_input(), {}).hpgl);
  check_golden("surface_5x4.hpgl", plot_hpgl(golden_surface(), {}).hpgl);
  check_golden("surface_5x4_a3_absolute.hpgl", plot_hpgl(golden_surface(), {Paper::a3, true}).hpgl);
}

TEST_CASE("golden: SVG") {
  check_golden("input_3x4.svg", svg_of(golden_input()));
  check_golden("surface_5x4.svg", svg_of(golden_surface()));
}

}  // namespace igds::test::devices
