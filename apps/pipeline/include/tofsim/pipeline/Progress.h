#pragma once
// Progress of long work on stderr: "render: segments 3/10, 12 s left".
// Rewrites one line on a terminal, prints at most one line every few seconds
// otherwise (CI logs), and nothing when quiet.

#include <chrono>
#include <cstddef>
#include <string>

namespace tofsim::pipeline {

class Progress {
 public:
  Progress(std::string task, bool quiet);
  ~Progress();
  /// Throws tofsim::Interrupted when SIGINT/SIGTERM arrived (util/Interrupt.h).
  void update(std::size_t done, std::size_t total, const std::string& what);
  void message(const std::string& text) const;

 private:
  std::string task_;
  bool quiet_;
  bool terminal_;
  bool lineOpen_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastPrint_;
};

}  // namespace tofsim::pipeline
