// The main of every test binary: doctest's, and under CTest (IGDS_UNDER_CTEST, set by
// tests/support/list_tests.cmake) a run whose --test-case chose no case fails. Each CTest test is
// one case chosen by its name; a name that CMake or doctest reads otherwise (a semicolon cut it
// in two once) would otherwise pass without running anything.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>

namespace {

unsigned cases_chosen = 0;

// Counts the cases the filters chose, and does nothing else.
struct CasesChosen : doctest::IReporter {
  explicit CasesChosen(const doctest::ContextOptions&) {}
  void report_query(const doctest::QueryData&) override {}
  void test_run_start() override {}
  void test_run_end(const doctest::TestRunStats& stats) override {
    cases_chosen = stats.numTestCasesPassingFilters;
  }
  void test_case_start(const doctest::TestCaseData&) override {}
  void test_case_reenter(const doctest::TestCaseData&) override {}
  void test_case_end(const doctest::CurrentTestCaseStats&) override {}
  void test_case_exception(const doctest::TestCaseException&) override {}
  void subcase_start(const doctest::SubcaseSignature&) override {}
  void subcase_end() override {}
  void log_assert(const doctest::AssertData&) override {}
  void log_message(const doctest::MessageData&) override {}
  void test_case_skipped(const doctest::TestCaseData&) override {}
};

REGISTER_LISTENER("cases_chosen", 1, CasesChosen);

}  // namespace

int main(int argc, char** argv) {
  doctest::Context context(argc, argv);
  const int status = context.run();
  if (context.shouldExit() || status != 0) return status;
  if (std::getenv("IGDS_UNDER_CTEST") != nullptr && cases_chosen == 0) {
    std::fputs("no test case has the name CTest gave\n", stderr);
    return 1;
  }
  return status;
}
