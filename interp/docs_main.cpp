// igds-docs man|man-tek|completion: writes igds(1), igds-tek(1) or the bash completion of igds to
// standard output, from the declarations they describe (interp/manual.h). Run at build time.
#include <fmt/format.h>

#include <string_view>

#include "interp/manual.h"
#include "interp/version.h"

int main(int argc, char** argv) {
  const std::string_view what = argc > 1 ? argv[1] : "";
  if (what == "man" && argc == 3) {
    fmt::print("{}", igds::manual_page(IGDS_VERSION, argv[2]));
  } else if (what == "man-tek" && argc == 3) {
    fmt::print("{}", igds::launcher_page(IGDS_VERSION, argv[2]));
  } else if (what == "completion" && argc == 2) {
    fmt::print("{}", igds::bash_completion());
  } else {
    fmt::print(stderr, "usage: igds-docs man DATE | man-tek DATE | completion\n");
    return 2;
  }
  return 0;
}
