#include "tofsim/util/AtomicFile.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include "tofsim/util/Error.h"

namespace tofsim {

namespace {
std::string errnoText() { return std::strerror(errno); }
}  // namespace

AtomicFile::AtomicFile(std::filesystem::path finalPath) : finalPath_(std::move(finalPath)) {
  tempPath_ = finalPath_;
  tempPath_ += ".tmp-" + std::to_string(::getpid());
  file_ = std::fopen(tempPath_.c_str(), "wb");
  if (!file_) {
    throw InputError(FileLoc{finalPath_.string()}, "", "cannot open for writing: " + errnoText());
  }
}

AtomicFile::~AtomicFile() { discard(); }

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : finalPath_(std::move(other.finalPath_)),
      tempPath_(std::move(other.tempPath_)),
      file_(std::exchange(other.file_, nullptr)) {}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    finalPath_ = std::move(other.finalPath_);
    tempPath_ = std::move(other.tempPath_);
    file_ = std::exchange(other.file_, nullptr);
  }
  return *this;
}

void AtomicFile::write(const void* data, std::size_t bytes) {
  TOFSIM_CHECK_MSG(file_, "write after commit");
  if (bytes == 0) return;
  if (std::fwrite(data, 1, bytes, file_) != bytes) {
    throw InputError(FileLoc{finalPath_.string()}, "", "write failed: " + errnoText());
  }
}

void AtomicFile::writeAt(std::size_t offset, const void* data, std::size_t bytes) {
  TOFSIM_CHECK_MSG(file_, "write after commit");
  const long back = std::ftell(file_);
  if (std::fseek(file_, static_cast<long>(offset), SEEK_SET) != 0 ||
      std::fwrite(data, 1, bytes, file_) != bytes || std::fseek(file_, back, SEEK_SET) != 0) {
    throw InputError(FileLoc{finalPath_.string()}, "", "write failed: " + errnoText());
  }
}

void AtomicFile::commit() {
  TOFSIM_CHECK_MSG(file_, "commit twice");
  // fflush + fsync before rename: a crash after the rename must not expose a
  // file whose data blocks never reached the disk.
  const bool ok = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  const int closeResult = std::fclose(file_);
  file_ = nullptr;
  if (!ok || closeResult != 0) {
    const std::string why = errnoText();
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
  if (file_) {
    std::fclose(file_);
    file_ = nullptr;
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
