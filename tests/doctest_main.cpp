// doctest's main, plus two guards so that ctest never shows as passed a test that did not run:
// the exit code of skipped tests (support/skip.hpp), and a failure when no test case matched the
// filters (ctest runs each test by name: a renamed test, or a name CMake split at a ';', would
// otherwise run nothing and pass).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>

#include "support/skip.hpp"

namespace {

/// Test cases started and skipped in this process.
struct SkipTally {
    int started = 0;
    int skipped = 0;
    bool current_skipped = false;
    bool queried = false;  ///< --list-test-cases, --count...: nothing is meant to run
};

SkipTally tally;

/// Counts test cases as they start and end; COLLIDE_SKIP_TEST marks the current one.
class SkipListener final : public doctest::IReporter {
  public:
    explicit SkipListener(const doctest::ContextOptions& /*options*/) {}

    void test_case_start(const doctest::TestCaseData& /*data*/) override {
        ++tally.started;
        tally.current_skipped = false;
    }
    void test_case_end(const doctest::CurrentTestCaseStats& /*stats*/) override {
        if (tally.current_skipped) ++tally.skipped;
    }

    void report_query(const doctest::QueryData& /*data*/) override { tally.queried = true; }
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats& /*stats*/) override {}
    void test_case_reenter(const doctest::TestCaseData& /*data*/) override {}
    void test_case_exception(const doctest::TestCaseException& /*e*/) override {}
    void subcase_start(const doctest::SubcaseSignature& /*signature*/) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData& /*data*/) override {}
    void log_message(const doctest::MessageData& /*data*/) override {}
    void test_case_skipped(const doctest::TestCaseData& /*data*/) override {}
};

}  // namespace

DOCTEST_REGISTER_LISTENER("collide_skips", 1, SkipListener);

void collide::test::note_skipped() {
    tally.current_skipped = true;
}

int main(int argc, char** argv) {
    doctest::Context context(argc, argv);
    const int result = context.run();
    if (context.shouldExit() || result != 0 || tally.queried) return result;
    if (tally.started == 0) {
        std::fputs("no test case matched the filters: nothing ran\n", stderr);
        return 1;
    }
    const bool all_skipped = tally.started > 0 && tally.skipped == tally.started;
    return all_skipped ? collide::test::skip_exit_code : result;
}
