// The output folder's lock and its all-or-nothing replacement.

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include "support/TempDir.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/StagedFolder.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class StagedFolderTest : public test::TempDirTest {};

TEST_F(StagedFolderTest, CommitReplacesTheWholeSetAndDropsWhatTheNewRunDidNotWrite) {
  const fs::path out = dir_ / "out";
  write(out / "a.txt", "old a");
  write(out / "sensors" / "old" / "x", "old sensor");
  write(out / "log.txt", "log");
  {
    StagedFolder folder(out, [](const std::string& name) { return name == "log.txt"; });
    write(folder.staging() / "a.txt", "new a");
    write(folder.staging() / "b.txt", "new b");
    EXPECT_EQ(read(out / "a.txt"), "old a") << "nothing changes before the commit";
    EXPECT_TRUE(folder.commit());
  }
  EXPECT_EQ(read(out / "a.txt"), "new a");
  EXPECT_EQ(read(out / "b.txt"), "new b");
  EXPECT_EQ(read(out / "log.txt"), "log") << "kept entries are carried over";
  EXPECT_FALSE(fs::exists(out / "sensors"));
  for (const auto& e : fs::directory_iterator(dir_)) {
    EXPECT_EQ(e.path().filename(), "out") << "no staging folder left beside";
  }
}

TEST_F(StagedFolderTest, WithoutCommitTheEarlierSetStaysAndAFolderItMadeGoes) {
  const fs::path out = dir_ / "out";
  write(out / "a.txt", "old a");
  {
    StagedFolder folder(out);
    write(folder.staging() / "a.txt", "new a");
  }
  EXPECT_EQ(read(out / "a.txt"), "old a");
  {
    StagedFolder fresh(dir_ / "fresh");
    EXPECT_TRUE(fresh.created());
    write(fresh.staging() / "a.txt", "x");
  }
  EXPECT_FALSE(fs::exists(dir_ / "fresh"));
}

TEST_F(StagedFolderTest, ASecondWriterFailsNamingTheFolderAndThePid) {
  const fs::path out = dir_ / "out";
  StagedFolder first(out);
  try {
    StagedFolder second(out);
    FAIL() << "the second writer got the lock";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(out.string()), std::string::npos) << what;
    EXPECT_NE(what.find("pid " + std::to_string(::getpid())), std::string::npos) << what;
  }
  EXPECT_EQ(folderLockHolder(out), ::getpid());
}

TEST_F(StagedFolderTest, TheLockSurvivesTheSwap) {
  const fs::path out = dir_ / "out";
  StagedFolder first(out);
  write(first.staging() / "a.txt", "a");
  first.commit();
  // The folder's inode changed; its lock file is still the held one.
  EXPECT_THROW(StagedFolder second(out), InputError);
}

TEST_F(StagedFolderTest, DeadWritersStagingIsRemovedByTheNextWriter) {
  const fs::path out = dir_ / "out";
  write(out / "a.txt", "a");
  write(dir_ / ".out.tofsim-staging-999999" / "transient.npy.tmp-999999", "half");
  { StagedFolder folder(out); }
  EXPECT_FALSE(fs::exists(dir_ / ".out.tofsim-staging-999999"));
  EXPECT_EQ(read(out / "a.txt"), "a");
  EXPECT_EQ(folderLockHolder(out), std::nullopt);
}

TEST_F(StagedFolderTest, APathThatIsAFileIsRejected) {
  write(dir_ / "file", "keep");
  EXPECT_THROW(StagedFolder folder(dir_ / "file"), InputError);
  EXPECT_EQ(read(dir_ / "file"), "keep");
}

TEST_F(StagedFolderTest, ALinkAtTheLockIsNeverWrittenThrough) {
  const fs::path out = dir_ / "out";
  write(dir_ / "victim.txt", "precious");
  fs::create_directories(out);
  fs::create_symlink("../victim.txt", out / FolderLock::kFileName);
  try {
    StagedFolder folder(out);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.location().file, (out / FolderLock::kFileName).string());
    EXPECT_NE(std::string(e.what()).find("symbolic link"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(dir_ / "victim.txt"), "precious");
  EXPECT_EQ(folderLockHolder(out), std::nullopt);  // nor read through
}

TEST_F(StagedFolderTest, AFolderGivenAsALinkIsWrittenThroughAndStaysALink) {
  const fs::path real = dir_ / "real", link = dir_ / "link";
  write(real / "old.txt", "old");
  fs::create_directory_symlink("real", link);
  {
    StagedFolder folder(link);
    EXPECT_EQ(folder.linkedFrom(), link);
    EXPECT_EQ(folder.folder(), fs::canonical(real));
    write(folder.staging() / "new.txt", "new");
    EXPECT_TRUE(folder.commit());
  }
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read(real / "new.txt"), "new");
  EXPECT_FALSE(fs::exists(real / "old.txt"));
  write(dir_ / "file.txt", "keep");
  fs::create_symlink("file.txt", dir_ / "to_file");
  EXPECT_THROW(StagedFolder folder(dir_ / "to_file"), InputError);
  EXPECT_EQ(read(dir_ / "file.txt"), "keep");
  fs::create_symlink("nowhere", dir_ / "dangling");
  EXPECT_THROW(StagedFolder folder(dir_ / "dangling"), InputError);
  EXPECT_FALSE(fs::exists(dir_ / "nowhere"));
}

}  // namespace
}  // namespace tofsim
