// Nothing followed (issue 39): a link, a folder or a FIFO at the output
// folder's lock file is an error naming it, and the link's target is never
// written; an output folder given as a link to a directory is written
// through (the results land in its target, the link stays a link, the run
// says so), a link to anything else is a located error; an empty -o is a
// usage error naming the option. Through the CLI on the CPU backend
// ($TOFSIM_TEST_CLI runs them against another build).

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

// The demo scene at 8 x 8, 50 bins, no sensors, no video: under a second.
const std::string kTiny =
    " --set render.backend=cpu --set camera.resolution=[8,8] --set time.bins=50"
    " --set sensors=[] --set output.video=false";

void writeFile(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class OutputFolderLinksTest : public test::TempDirTest {
 protected:
  test::CommandResult render(const fs::path& out, const std::string& more = " -q") {
    return test::runCli("render " + test::kCornellConfig + " -o " + out.string() + kTiny + more);
  }
  // No staging folder beside `folder` nor inside it.
  void expectNoStaging(const fs::path& folder) {
    for (const fs::path& dir : {folder.parent_path(), folder}) {
      if (!fs::is_directory(dir)) continue;
      for (const auto& e : fs::directory_iterator(dir)) {
        EXPECT_FALSE(has(e.path().filename().string(), ".tofsim-staging-")) << e.path();
      }
    }
  }
};

TEST_F(OutputFolderLinksTest, ALinkAtTheLockFileIsRefusedAndItsTargetUntouched) {
  const fs::path out = dir_ / "out", victim = dir_ / "victim.txt";
  fs::create_directories(out);
  writeFile(victim, "precious\n");
  fs::create_symlink("../victim.txt", out / ".tofsim.lock");
  const test::CommandResult r = render(out);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(has(r.output, (out / ".tofsim.lock").string() + ": ") &&
              has(r.output, "symbolic link"))
      << r.output;
  EXPECT_EQ(test::fileBytes(victim.string()), "precious\n");
  EXPECT_TRUE(fs::is_symlink(out / ".tofsim.lock"));
  EXPECT_TRUE(test::visibleFiles(out).empty()) << "nothing rendered";
  expectNoStaging(out);
}

TEST_F(OutputFolderLinksTest, ALockPathThatIsAFolderOrAFifoIsRefusedNamingIt) {
  const fs::path out = dir_ / "out", lock = out / ".tofsim.lock";
  fs::create_directories(lock);
  test::CommandResult r = render(out);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(has(r.output, lock.string() + ": ") && has(r.output, "a directory")) << r.output;
  fs::remove(lock);
  ASSERT_EQ(::mkfifo(lock.c_str(), 0644), 0);
  r = render(out);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(has(r.output, lock.string() + ": ") && has(r.output, "FIFO")) << r.output;
  EXPECT_TRUE(test::visibleFiles(out).empty()) << "nothing rendered";
  expectNoStaging(out);
}

TEST_F(OutputFolderLinksTest, AnOutputFolderThatIsALinkIsWrittenThrough) {
  const fs::path real = dir_ / "real", out = dir_ / "out";
  fs::create_directories(real);
  fs::create_directory_symlink("real", out);
  for (int run = 0; run < 2; ++run) {  // into an empty target, then over the first set
    const test::CommandResult r = render(out, " --set render.seed=" + std::to_string(run + 1));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(has(r.output, out.string() + " -> " + fs::canonical(real).string() +
                                  ": writing into the link's target"))
        << r.output;
    EXPECT_TRUE(fs::is_symlink(out)) << "the link stays a link";
    EXPECT_TRUE(fs::exists(real / "transient.npy")) << "the results are in the target";
    EXPECT_TRUE(has(test::fileBytes((real / "transient.json").string()),
                    "\"seed\": " + std::to_string(run + 1)));
    expectNoStaging(real);
    expectNoStaging(out);
  }
}

TEST_F(OutputFolderLinksTest, ALinkToAFileOrToNothingIsALocatedError) {
  const fs::path dangling = dir_ / "dangling", toFile = dir_ / "to_file";
  fs::create_symlink("missing", dangling);
  test::CommandResult r = render(dangling);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(has(r.output, dangling.string() + ": ") && has(r.output, "does not exist"))
      << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "missing")) << "not made through the link";

  writeFile(dir_ / "file.txt", "keep\n");
  fs::create_symlink("file.txt", toFile);
  r = render(toFile);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(has(r.output, toFile.string() + ": ") && has(r.output, "not a directory"))
      << r.output;
  EXPECT_EQ(test::fileBytes((dir_ / "file.txt").string()), "keep\n");
}

TEST_F(OutputFolderLinksTest, AnEmptyOutputOptionIsAUsageError) {
  // Else "" means "no -o": the config's output.directory.
  const std::string fallback = " --set output.directory=" + (dir_ / "fallback").string();
  const fs::path a = dir_ / "a";
  for (const std::string& args :
       {"render " + test::kCornellConfig + " -o ''" + kTiny + fallback,
        "render " + test::kCornellConfig + " --output ''" + kTiny + fallback,
        "sense " + test::kCornellConfig + " --volume " + a.string() + " -o ''",
        "compare " + a.string() + " " + a.string() + " -o ''"}) {
    const test::CommandResult r = test::runCli(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    EXPECT_TRUE(has(r.output, "--output") && has(r.output, "empty")) << args << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "fallback"));
}

}  // namespace
}  // namespace tofsim
