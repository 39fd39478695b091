// ChildStderr: what a forked child writes to stderr reaches its parent
// through the file, not the parent's own stderr; Tail keeps the end and
// AfterExit makes it the end of a dead child's reason.
#include "milp/internal/child_stderr.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

namespace thrustsched::milp::internal {
namespace {

// Forks a child that writes `text` to its stderr and exits with code 3.
int RunChildThatSays(const ChildStderr& err, const std::string& text) {
  const pid_t pid = fork();
  if (pid == 0) {
    err.AttachInChild();
    std::fputs(text.c_str(), stderr);
    std::fflush(stderr);
    _exit(3);
  }
  int wstatus = 0;
  while (waitpid(pid, &wstatus, 0) < 0) {
  }
  return WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1;
}

TEST(ChildStderr, KeepsWhatTheChildWroteForTheParent) {
  const ChildStderr err;
  const std::string said =
      "ClpPrimalColumnSteepest.cpp:727: Assertion `model_->reducedCost(bestSequence) < 0.0' "
      "failed.\n";
  testing::internal::CaptureStderr();
  const int code = RunChildThatSays(err, said);
  const std::string on_parents_stderr = testing::internal::GetCapturedStderr();
  ASSERT_EQ(code, 3);
  EXPECT_EQ(on_parents_stderr, "");
  EXPECT_EQ(err.Tail(2000), said.substr(0, said.size() - 1));  // trailing newline dropped
  EXPECT_EQ(err.Tail(13), "0.0' failed.");                     // the last 13 bytes, newline dropped
  // A child that died: its words end the reason.
  EXPECT_EQ(err.AfterExit(/*died=*/true), "; it wrote: " + said.substr(0, said.size() - 1));
}

TEST(ChildStderr, IsEmptyWhenTheChildSaysNothing) {
  const ChildStderr err;
  ASSERT_EQ(RunChildThatSays(err, ""), 3);
  EXPECT_EQ(err.Tail(2000), "");
  EXPECT_EQ(err.AfterExit(/*died=*/true), "");
}

}  // namespace
}  // namespace thrustsched::milp::internal
