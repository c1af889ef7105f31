// A pending SIGINT/SIGTERM ends long work at its next progress report with
// tofsim::Interrupted, and unwinding removes every temporary file.

#include <gtest/gtest.h>

#include <csignal>

#include "support/TempDir.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/Progress.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim {
namespace {

class InterruptTest : public test::TempDirTest {
 protected:
  void TearDown() override {
    setPendingInterruptForTesting(0);
    test::TempDirTest::TearDown();
  }
};

TEST_F(InterruptTest, ProgressThrowsWithShellExitCode) {
  pipeline::Progress progress("test", /*quiet=*/true);
  EXPECT_NO_THROW(progress.update(1, 10, "steps"));
  setPendingInterruptForTesting(SIGINT);
  try {
    progress.update(2, 10, "steps");
    FAIL() << "no Interrupted";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.exitCode(), 130);
    EXPECT_NE(std::string(e.what()).find("SIGINT"), std::string::npos);
  }
  setPendingInterruptForTesting(SIGTERM);
  EXPECT_EQ(Interrupted(pendingInterrupt()).exitCode(), 143);
}

TEST_F(InterruptTest, UnwindingRemovesStreamedTemporaries) {
  try {
    io::NpyStreamWriter writer(dir_ / "transient.npy", {2, 2});
    const float half[2] = {1.0f, 2.0f};
    writer.append(half, 2);
    setPendingInterruptForTesting(SIGTERM);
    throwIfInterrupted();
  } catch (const Interrupted&) {
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

TEST_F(InterruptTest, RealSignalSetsTheFlag) {
  installInterruptHandlers();
  std::raise(SIGINT);
  EXPECT_EQ(pendingInterrupt(), SIGINT);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

}  // namespace
}  // namespace tofsim
