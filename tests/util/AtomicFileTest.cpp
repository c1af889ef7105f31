// AtomicFile: whole or nothing, byte for byte, with large files' blocks
// written past the page cache (O_DIRECT) where the file system takes it.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/TempDir.h"
#include "tofsim/util/AtomicFile.h"
#include "tofsim/util/Error.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

std::vector<char> read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Bytes that no two blocks share: a misplaced block or a dropped tail shows.
std::vector<char> pattern(std::size_t n) {
  std::vector<char> bytes(n);
  uint32_t state = 2463534242u;
  for (char& b : bytes) {
    state ^= state << 13, state ^= state >> 17, state ^= state << 5;
    b = static_cast<char>(state >> 24);
  }
  return bytes;
}

// Writes `bytes` in pieces of 1, 7, 4096, 100003, ... bytes: the staging
// buffer's boundaries fall inside writes and between them.
void writeInPieces(AtomicFile& file, const std::vector<char>& bytes) {
  const std::size_t pieces[] = {1, 7, 4096, 100003, 3 << 20, 65536, 511};
  std::size_t at = 0;
  for (std::size_t i = 0; at < bytes.size(); ++i) {
    const std::size_t n = std::min(pieces[i % std::size(pieces)], bytes.size() - at);
    file.write(bytes.data() + at, n);
    at += n;
  }
}

// Whether the directory's file system takes O_DIRECT (tmpfs before Linux 6.6 does not).
bool takesDirectIo(const fs::path& dir) {
  const fs::path probe = dir / "probe";
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_DIRECT, 0600);
  if (fd >= 0) ::close(fd);
  fs::remove(probe);
  return fd >= 0;
}

class AtomicFileTest : public test::TempDirTest {};

TEST_F(AtomicFileTest, SmallFileIsWrittenBufferedAndWhole) {
  const fs::path path = dir_ / "small.txt";
  AtomicFile file(path);
  file.write("hello, ");
  file.write("world");
  EXPECT_TRUE(fs::exists(file.tempPath()));
  EXPECT_FALSE(fs::exists(path));
  file.commit();
  EXPECT_FALSE(file.wroteDirect());
  const std::vector<char> got = read(path);
  EXPECT_EQ(std::string(got.begin(), got.end()), "hello, world");
  EXPECT_EQ(filesIn(dir_), std::vector<std::string>{"small.txt"});
}

TEST_F(AtomicFileTest, LargeFileIsByteExactAndGoesDirectWhereTheFileSystemTakesIt) {
  const fs::path path = dir_ / "large.bin";
  // Two whole staging buffers and a tail that is not a whole block.
  const std::vector<char> bytes = pattern(2 * AtomicFile::kDirectFrom + 12345);
  AtomicFile file(path);
  writeInPieces(file, bytes);
  file.commit();
  EXPECT_EQ(file.wroteDirect(), takesDirectIo(dir_));
  EXPECT_EQ(read(path), bytes);
  EXPECT_EQ(filesIn(dir_), std::vector<std::string>{"large.bin"});
}

TEST_F(AtomicFileTest, ExactlyTheStagingBufferAndOneByteMore) {
  for (const std::size_t n : {AtomicFile::kDirectFrom, AtomicFile::kDirectFrom + 1}) {
    const fs::path path = dir_ / ("f" + std::to_string(n));
    const std::vector<char> bytes = pattern(n);
    AtomicFile file(path);
    file.write(bytes.data(), bytes.size());
    file.commit();
    EXPECT_EQ(read(path), bytes) << n;
  }
}

TEST_F(AtomicFileTest, WithoutCommitTheOldFileStaysAndNoTemporaryIsLeft) {
  const fs::path path = dir_ / "volume.npy";
  writeFileAtomically(path, "old");
  {
    AtomicFile file(path);
    const std::vector<char> bytes = pattern(AtomicFile::kDirectFrom + 4096);
    file.write(bytes.data(), bytes.size());  // past the staging buffer: on disk
  }
  const std::vector<char> got = read(path);
  EXPECT_EQ(std::string(got.begin(), got.end()), "old");
  EXPECT_EQ(filesIn(dir_), std::vector<std::string>{"volume.npy"});
}

TEST_F(AtomicFileTest, MovedFromFileDoesNotRemoveTheTemporary) {
  const fs::path path = dir_ / "moved.txt";
  AtomicFile first(path);
  first.write("data");
  AtomicFile second = std::move(first);
  second.commit();
  const std::vector<char> got = read(path);
  EXPECT_EQ(std::string(got.begin(), got.end()), "data");
}

// A full disk half-way through the direct writes (the file-size limit stands
// in for it: write() fails with EFBIG): a located error, the old file kept.
TEST_F(AtomicFileTest, WriteFailingHalfWayIsAnErrorAndLeavesTheOldFile) {
  const fs::path path = dir_ / "volume.npy";
  writeFileAtomically(path, "old");
  const std::vector<char> bytes = pattern(3 * AtomicFile::kDirectFrom);
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = AtomicFile::kDirectFrom + (1 << 20);
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    AtomicFile file(path);
    file.write(bytes.data(), bytes.size());
    file.commit();
  } catch (const InputError& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("write failed"), std::string::npos) << message;
  const std::vector<char> got = read(path);
  EXPECT_EQ(std::string(got.begin(), got.end()), "old");
  EXPECT_EQ(filesIn(dir_), std::vector<std::string>{"volume.npy"});
}

// The temporary's name is guessable ("<name>.tmp-<pid>"): a link planted
// there must neither be written through nor end up as the file.
TEST_F(AtomicFileTest, ALinkAtTheTemporaryNameIsNotFollowed) {
  const fs::path victim = dir_ / "victim.txt", file = dir_ / "out.json";
  { std::ofstream(victim) << "precious"; }
  fs::create_symlink(victim, fs::path(file.string() + ".tmp-" + std::to_string(::getpid())));
  writeFileAtomically(file, "new");
  EXPECT_EQ(read(victim), std::vector<char>({'p', 'r', 'e', 'c', 'i', 'o', 'u', 's'}));
  EXPECT_FALSE(fs::is_symlink(file));
  EXPECT_EQ(read(file), std::vector<char>({'n', 'e', 'w'}));
}

}  // namespace
}  // namespace tofsim
