// A test that cannot run here (a tool that is not installed, a file system that cannot be
// mounted) says why and is counted as skipped, never as passed:
//  - under CTest (one test a process), the process ends with status 77, which CTest shows as
//    "Skipped" in its summary;
//  - with IGDS_NO_SKIPS=1 in the environment (scripts/test and CI, which install every tool),
//    the test fails instead, so that nothing passes there without having run;
//  - run by hand, a warning says so and the test returns.
#pragma once

#include <string_view>

namespace igds::test {

// True when the caller must return (the test is skipped or has failed).
bool skip_now(std::string_view why);

}  // namespace igds::test

// Inside a test case: IGDS_SKIP_UNLESS(have_program("tek2plot"), "tek2plot (plotutils) is not
// installed").
#define IGDS_SKIP_UNLESS(condition, why)                     \
  do {                                                       \
    if (!(condition) && ::igds::test::skip_now(why)) return; \
  } while (false)
