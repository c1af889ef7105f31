#include "tofsim/util/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <utility>

#include "tofsim/util/Error.h"

namespace tofsim {

namespace {

std::string errnoText() { return std::strerror(errno); }

// O_DIRECT's alignment of buffers, offsets and lengths: the page size covers
// every logical block size Linux file systems use.
constexpr std::size_t kAlign = 4096;
constexpr std::size_t kFirstStaging = std::size_t{64} << 10;  // small files stay small

static_assert(AtomicFile::kDirectFrom % kAlign == 0);

}  // namespace

void AtomicFile::FreeStaging::operator()(char* p) const noexcept { std::free(p); }

AtomicFile::AtomicFile(std::filesystem::path finalPath) : finalPath_(std::move(finalPath)) {
  tempPath_ = finalPath_;
  tempPath_ += ".tmp-" + std::to_string(::getpid());
  // A new file, never one met at that name: O_EXCL does not follow a link
  // there (one planted at a guessable name cannot redirect the write). What
  // is there was left by a dead process of the same pid, or planted: only
  // the name goes.
  const int flags = O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC;
  fd_ = ::open(tempPath_.c_str(), flags, 0666);
  if (fd_ < 0 && errno == EEXIST && ::unlink(tempPath_.c_str()) == 0) {
    fd_ = ::open(tempPath_.c_str(), flags, 0666);
  }
  if (fd_ < 0) {
    throw InputError(FileLoc{finalPath_.string()}, "", "cannot open for writing: " + errnoText());
  }
}

AtomicFile::~AtomicFile() { discard(); }

AtomicFile::AtomicFile(AtomicFile&& other) noexcept { takeFrom(other); }

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    takeFrom(other);
  }
  return *this;
}

// Moves every member over, leaving `other` without a file (its destructor
// then removes nothing).
void AtomicFile::takeFrom(AtomicFile& other) noexcept {
  finalPath_ = std::move(other.finalPath_);
  tempPath_ = std::move(other.tempPath_);
  fd_ = std::exchange(other.fd_, -1);
  staging_ = std::move(other.staging_);
  capacity_ = std::exchange(other.capacity_, 0);
  staged_ = std::exchange(other.staged_, 0);
  written_ = std::exchange(other.written_, 0);
  direct_ = std::exchange(other.direct_, false);
  wroteDirect_ = std::exchange(other.wroteDirect_, false);
}

// Grows the staging buffer to hold `atLeast` bytes, up to kDirectFrom.
void AtomicFile::stage(std::size_t atLeast) {
  std::size_t capacity = std::max(capacity_, kFirstStaging);
  while (capacity < atLeast && capacity < kDirectFrom) capacity *= 2;
  capacity = std::min(capacity, kDirectFrom);
  if (capacity == capacity_) return;
  char* grown = static_cast<char*>(std::aligned_alloc(kAlign, capacity));
  if (!grown) throw std::bad_alloc();
  if (staged_ > 0) std::memcpy(grown, staging_.get(), staged_);
  staging_.reset(grown);
  capacity_ = capacity;
}

void AtomicFile::write(const void* data, std::size_t bytes) {
  TOFSIM_CHECK_MSG(fd_ >= 0, "write after commit");
  const char* from = static_cast<const char*>(data);
  while (bytes > 0) {
    if (staged_ == capacity_) {
      if (capacity_ < kDirectFrom) {
        stage(staged_ + bytes);
      } else {
        flushStaged();
      }
    }
    const std::size_t chunk = std::min(bytes, capacity_ - staged_);
    std::memcpy(staging_.get() + staged_, from, chunk);
    staged_ += chunk, from += chunk, bytes -= chunk;
  }
}

// A full staging buffer (kDirectFrom bytes, at an offset that is a multiple of
// it) to the file: direct from the first one on, where the file system lets
// (tried once: after a refusal the file stays buffered).
void AtomicFile::flushStaged() {
  if (written_ == 0) setDirect(true);
  writeOut(staging_.get(), staged_);
  staged_ = 0;
}

void AtomicFile::setDirect(bool on) {
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags < 0) return;
  if (::fcntl(fd_, F_SETFL, on ? (flags | O_DIRECT) : (flags & ~O_DIRECT)) == 0) {
    direct_ = on;
  }
}

void AtomicFile::writeOut(const char* data, std::size_t bytes) {
  while (bytes > 0) {
    const ssize_t n = ::pwrite(fd_, data, bytes, static_cast<off_t>(written_));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EINVAL && direct_) {
      // A file system that takes the flag but not the write (or a short
      // direct write left the offset unaligned): buffered from here on.
      setDirect(false);
      if (!direct_) continue;
    }
    if (n <= 0) {
      throw InputError(FileLoc{finalPath_.string()}, "",
                       "write failed: " + (n < 0 ? errnoText() : std::string("no progress")));
    }
    wroteDirect_ = wroteDirect_ || direct_;
    data += n, bytes -= static_cast<std::size_t>(n), written_ += static_cast<std::size_t>(n);
  }
}

void AtomicFile::commit() {
  TOFSIM_CHECK_MSG(fd_ >= 0, "commit twice");
  try {
    // The tail is not a whole number of blocks: buffered.
    if (direct_ && staged_ % kAlign != 0) setDirect(false);
    writeOut(staging_.get(), staged_);
    staged_ = 0;
    staging_.reset();
  } catch (...) {
    discard();
    throw;
  }
  // fsync before rename: a crash after the rename must not expose a file
  // whose data blocks never reached the disk.
  std::string why;  // the first failure's
  if (::fsync(fd_) != 0) why = errnoText();
  if (::close(fd_) != 0 && why.empty()) why = errnoText();
  fd_ = -1;
  if (!why.empty()) {
    std::filesystem::remove(tempPath_);
    throw InputError(FileLoc{finalPath_.string()}, "", "write failed: " + why);
  }
  std::error_code ec;
  std::filesystem::rename(tempPath_, finalPath_, ec);
  if (ec) {
    std::filesystem::remove(tempPath_);
    throw InputError(FileLoc{finalPath_.string()}, "", "cannot rename into place: " + ec.message());
  }
}

void AtomicFile::discard() noexcept {
  staging_.reset();
  capacity_ = staged_ = 0;
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
    std::error_code ec;
    std::filesystem::remove(tempPath_, ec);
  }
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
  AtomicFile file(path);
  file.write(contents);
  file.commit();
}

}  // namespace tofsim
