#include "tofsim/util/Interrupt.h"

#include <atomic>
#include <csignal>
#include <string>

namespace tofsim {

namespace {
// Lock-free, so writing it from a signal handler is async-signal-safe.
std::atomic<int> gPending{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void onSignal(int signalNumber) { gPending.store(signalNumber); }

std::string signalName(int signalNumber) {
  switch (signalNumber) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "signal " + std::to_string(signalNumber);
  }
}
}  // namespace

Interrupted::Interrupted(int signalNumber)
    : std::runtime_error("interrupted by " + signalName(signalNumber) +
                         "; this run's partial outputs were removed, earlier results are unchanged"),
      signal_(signalNumber) {}

void installInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // the second signal takes the default action
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int pendingInterrupt() { return gPending.load(); }

void throwIfInterrupted() {
  if (const int s = gPending.load()) throw Interrupted(s);
}

void setPendingInterrupt(int signalNumber) { gPending.store(signalNumber); }

void setPendingInterruptForTesting(int signalNumber) { gPending.store(signalNumber); }

}  // namespace tofsim
