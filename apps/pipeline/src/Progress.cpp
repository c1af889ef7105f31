#include "tofsim/pipeline/Progress.h"

#include <unistd.h>

#include <cstdio>
#include <utility>

#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {

Progress::Progress(std::string task, bool quiet)
    : task_(std::move(task)),
      quiet_(quiet),
      terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      lastPrint_(start_) {}

Progress::~Progress() {
  if (lineOpen_) std::fputc('\n', stderr);
}

void Progress::update(std::size_t done, std::size_t total, const std::string& what) {
  // Long work reports progress often, so this is where SIGINT/SIGTERM end it
  // (quiet or not): the exception unwinds through the writers' destructors.
  throwIfInterrupted();
  if (quiet_ || total == 0) return;
  const auto now = std::chrono::steady_clock::now();
  const bool finished = done >= total;
  const double sinceLast = std::chrono::duration<double>(now - lastPrint_).count();
  if (!finished && sinceLast < (terminal_ ? 0.2 : 5.0)) return;
  lastPrint_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double left = done > 0 ? elapsed * static_cast<double>(total - done) / done : 0.0;
  char line[256];
  std::snprintf(line, sizeof line, "%s: %s %zu/%zu, %.1f s elapsed, %.1f s left", task_.c_str(),
                what.c_str(), done, total, elapsed, left);
  if (terminal_) {
    std::fprintf(stderr, "\r\033[K%s", line);
    lineOpen_ = !finished;
    if (finished) std::fputc('\n', stderr);
  } else {
    std::fprintf(stderr, "%s\n", line);
  }
  std::fflush(stderr);
}

void Progress::message(const std::string& text) const {
  if (quiet_) return;
  std::fprintf(stderr, "%s%s: %s\n", lineOpen_ ? "\n" : "", task_.c_str(), text.c_str());
}

}  // namespace tofsim::pipeline
