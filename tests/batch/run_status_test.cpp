// The status of a finished run: a scenario without expectations did not "pass" - nothing was checked.
#include <gtest/gtest.h>

#include "report/outputs.hpp"

namespace signalsim {
namespace {

ExpectationResult result(bool passed) {
  ExpectationResult r;
  r.description = "blinker_never: hazard";
  r.passed = passed;
  return r;
}

TEST(RunStatus, NoExpectationsIsItsOwnStatusNotPassed) {
  EXPECT_EQ(run_status({}), RunStatus::NoExpectations);
  EXPECT_EQ(to_string(RunStatus::NoExpectations), "no_expectations");
  EXPECT_EQ(run_status({result(true), result(true)}), RunStatus::Passed);
  EXPECT_EQ(to_string(RunStatus::Passed), "passed");
  EXPECT_EQ(run_status({result(true), result(false)}), RunStatus::Failed);
  EXPECT_EQ(to_string(RunStatus::Failed), "failed");
  EXPECT_EQ(to_string(RunStatus::Error), "error");
}

}  // namespace
}  // namespace signalsim
