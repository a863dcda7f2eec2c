#include "tests/support/skip.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace igds::test {

bool skip_now(std::string_view why) {
  const char* strict = std::getenv("IGDS_NO_SKIPS");
  if (strict && std::string_view(strict) == "1") {
    FAIL_CHECK("cannot run: " << why << " (IGDS_NO_SKIPS=1: every test must run)");
    return true;
  }
  const char* ctest = std::getenv("IGDS_UNDER_CTEST");
  if (ctest && std::string_view(ctest) == "1") {
    std::fprintf(stderr, "skipped: %.*s\n", static_cast<int>(why.size()), why.data());
    std::fflush(nullptr);
    std::_Exit(77);
  }
  WARN_MESSAGE(false, "skipped: " << why);
  return true;
}

}  // namespace igds::test
