#pragma once
// Files that appear whole or not at all: data goes to "<name>.tmp-<pid>" and is
// renamed over the final name only by commit(). A destructor without commit()
// (an exception, an interrupted run) removes the temporary, so a failed run
// never leaves a half-written file under the final name.

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace tofsim {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path finalPath);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&& other) noexcept;

  /// Appends bytes; throws InputError on a short write (disk full).
  void write(const void* data, std::size_t bytes);
  void write(std::string_view text) { write(text.data(), text.size()); }
  /// Writes at an absolute offset (used to patch headers of streamed files).
  void writeAt(std::size_t offset, const void* data, std::size_t bytes);

  /// Flushes, closes and renames onto the final path.
  void commit();

  const std::filesystem::path& tempPath() const { return tempPath_; }
  const std::filesystem::path& finalPath() const { return finalPath_; }

 private:
  void discard() noexcept;

  std::filesystem::path finalPath_;
  std::filesystem::path tempPath_;
  std::FILE* file_ = nullptr;
};

/// Writes a whole file atomically.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace tofsim
