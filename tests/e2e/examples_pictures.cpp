// The README's pictures of the examples (scripts/examples/NAME.png) are what igds draws today:
// scripts/pictures renders them afresh into a scratch folder and each is compared pixel by pixel
// with the one in the tree, so a change in drawing shows up here.
#include <doctest/doctest.h>

#include <cstdlib>

#include "tests/e2e/examples_support.h"
#include "tests/support/process.h"
#include "tests/support/skip.h"

namespace igds::test {

TEST_CASE("the README's pictures of the examples are the ones igds draws now") {
  for (const char* tool : {"tek2plot", "compare"}) {
    IGDS_SKIP_UNLESS(have_program(tool),
                     std::string(tool) + " is not installed (plotutils, imagemagick)");
  }
  TempDir fresh;
  auto made = run({(source_dir() / "scripts/pictures").string(), "--igds", igds_binary().string(),
                   "--out", fresh.path().string()});
  REQUIRE_MESSAGE(made.status == 0, made.err);
  for (const auto& e : examples()) {
    CAPTURE(e.name);
    auto kept = source_dir() / "scripts/examples" / (e.name + ".png");
    auto now = fresh.path() / (e.name + ".png");
    REQUIRE(std::filesystem::exists(kept));
    REQUIRE(std::filesystem::exists(now));
    // AE: the number of pixels that differ; compare prints it on stderr, exits 1 when any do.
    auto diff = run({"compare", "-metric", "AE", kept.string(), now.string(), "null:"});
    CHECK(diff.status != 2);
    double differing = std::atof(diff.err.c_str());
    CHECK_MESSAGE(differing <= 4, "pictures differ in " << diff.err
                                                        << " pixels: run scripts/pictures "
                                                           "and look at scripts/examples/"
                                                        << e.name << ".png");
  }
}

}  // namespace igds::test
