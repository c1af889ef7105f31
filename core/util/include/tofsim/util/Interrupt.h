#pragma once
// Ctrl-C and `kill` during long work: the CLI installs handlers for SIGINT
// and SIGTERM that only set a flag; long loops call throwIfInterrupted() where
// they report progress, so the stack unwinds normally and every destructor
// runs (AtomicFile removes its temporary: no half-written output remains).
//
// Interrupted is deliberately not an InputError: code that catches
// InputError to add context must not swallow or rewrap it.

#include <stdexcept>

namespace tofsim {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signalNumber);
  int signalNumber() const { return signal_; }
  /// The conventional shell exit status: 128 + signal (130 SIGINT, 143 SIGTERM).
  int exitCode() const { return 128 + signal_; }

 private:
  int signal_;
};

/// Installs the SIGINT/SIGTERM handlers (one-shot: a second signal kills the
/// process the default way, for a user who does not want to wait).
void installInterruptHandlers();
/// The signal received since installInterruptHandlers(), or 0.
int pendingInterrupt();
/// Throws Interrupted when a signal arrived.
void throwIfInterrupted();
/// Records `signalNumber` as arrived (0 clears). Async-signal-safe: for
/// handlers installed elsewhere, e.g. the Python module's SIGINT handler for
/// the duration of a render.
void setPendingInterrupt(int signalNumber);
/// Test hook: behaves as if `signalNumber` had arrived (0 clears).
void setPendingInterruptForTesting(int signalNumber);

}  // namespace tofsim
