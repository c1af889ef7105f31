#pragma once
// Private to the SPAD model: one pixel's detector as an event-driven state
// machine, the piece of issue 24's exact engine that drivers step through time
// (SpadEventEngine.h: one pixel alone; SpadArrayEvents.h: many, in time order).
// Adding an event kind: name it in EventKind; whoever causes it queues it
// with inject() (fire() for the pixel's own avalanches, a driver for another
// pixel's), and fire() says what its avalanche does beyond the common law.

#include <cstdint>
#include <vector>

#include "tofsim/sensors/Random.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::sensors::detail {

/// A moment of the detector's time: a laser cycle and a position in it, in
/// TDC bins (bin = floor(position); the laser period is the TDC range).
struct Moment {
  uint64_t cycle = 0;
  double position = 0.0;
  bool operator<(const Moment& o) const {
    return cycle < o.cycle || (cycle == o.cycle && position < o.position);
  }
};

/// What makes an avalanche: a primary (signal, ambient or dark: the pixel's
/// own flux), a release of its own traps, or an arrival from another pixel.
enum class EventKind { Primary, Afterpulse, Crosstalk };

/// An avalanche that happens at `at` if the detector is live then.
struct Event {
  Moment at;
  EventKind kind = EventKind::Primary;
  int64_t source = -1;  ///< the pixel that caused it (Crosstalk); -1: its own
};

/// Afterpulsing: each avalanche fills traps, released `count` at a time (a
/// Bernoulli(mean) or Poisson(mean) number per avalanche), each after a delay
/// from a mixture of exponentials (means delays_bins, weights, normalised
/// here) counted from the end of that avalanche's dead time; a release while
/// the detector is live is an avalanche, one while it is dead is lost. With
/// `reset` every avalanche empties the traps of the ones before (the renewal
/// model of the closed forms); without, releases stay queued.
struct AfterpulseLaw {
  enum class Count { Bernoulli, Poisson };
  Count count = Count::Bernoulli;
  double mean = 0.0;  ///< p (Bernoulli) or mu (Poisson); 0: none
  std::vector<double> delays_bins = {1.0};
  std::vector<double> weights = {1.0};
  /// A measured delay density in place of the mixture (non-empty): piecewise
  /// constant between table_edges_bins (increasing, from >= 0), table_cdf
  /// its distribution at those edges (0 .. 1). Delays by its exact inverse.
  std::vector<double> table_edges_bins;
  std::vector<double> table_cdf;
  bool reset = true;
  bool on() const { return mean > 0.0; }
  bool tabled() const { return !table_cdf.empty(); }
};

/// Fills law's table from `table` (seconds) on a TDC of this bin width: its
/// edges in bins and its distribution at them.
void setAfterpulseTable(AfterpulseLaw& law, const SpadAfterpulseTable& table, double binWidth_s);

/// One delay, in bins, by the inverse of the table's distribution at u in
/// [0, 1): uniform within the bin where table_cdf reaches u.
double tableDelay(const AfterpulseLaw& law, double u);

/// P(s <= delay < s + 1) for s = 0, 1, ... up to the table's last edge: the
/// release kernel in whole bins after the live moment (the fast path's).
std::vector<double> tableBinMasses(const AfterpulseLaw& law);

/// The laws of one pixel's detector and TDC.
struct DetectorLaws {
  /// After every avalanche (recorded or not) dead for the rest of its bin and
  /// deadBins more, then live again at a bin's start; it may span cycles.
  int32_t deadBins = 0;
  /// Recorded avalanches per laser cycle (a multi-stop TDC); 0: every one
  /// (free-running). Avalanches after the last stop still happen: dead time,
  /// afterpulses, crosstalk, but no count.
  int64_t stops = 1;
  AfterpulseLaw afterpulses;
  /// An array driver that sends crosstalk needs every avalanche even where
  /// none could change this pixel's counts (after the cycle's last stop).
  bool everyAvalanche = false;
};

/// No bin with flux whose dead time runs into the next cycle: then avalanches
/// after a cycle's last stop cannot change a later cycle (without afterpulses).
bool deadTimeEndsInItsCycle(const std::vector<double>& flux, int32_t deadBins);

/// One pixel's detector over `cycles` laser cycles, flux_i expected primaries
/// per cycle in bin i. A driver repeats: e = next(rng); stop when
/// e.at.cycle == cycles; fire(e, rng, h); it may inject() events from other
/// pixels in between (an arrival earlier than next() becomes next()).
/// Exact: primaries by inverting the cumulative flux from the moment the
/// detector is live again against an Exp(1) draw (kept until an avalanche
/// makes it stale: memoryless), whole empty cycles skipped at once.
class SpadDetector {
 public:
  SpadDetector(const std::vector<double>& flux, const DetectorLaws& laws, uint64_t cycles);

  /// The earliest avalanche to come if nothing is injected before it: the
  /// next primary or the earliest queued event while live. at.cycle ==
  /// cycles: none before the end.
  Event next(Rng& rng);
  /// Live at `m` (an event then would avalanche).
  bool canFire(const Moment& m) const { return !(m < liveFrom_); }
  /// Queues an event (another pixel's crosstalk arrival); lost if the
  /// detector is dead when it comes.
  void inject(const Event& e);
  /// The avalanche of `e` (from next(), so canFire(e.at)): a count in `h` if
  /// the TDC has a stop left in e's cycle, the dead time, the afterpulses it
  /// queues. True when it was recorded.
  bool fire(const Event& e, Rng& rng, std::vector<double>& h);

  Moment liveFrom() const { return liveFrom_; }
  uint64_t cycles() const { return cycles_; }
  int32_t bins() const { return K_; }

 private:
  Moment nextPrimary(Rng& rng) const;
  Moment firstOfCleanCycles(Rng& rng) const;
  void queueAfterpulses(Rng& rng);
  void popStale();

  const std::vector<double>& flux_;
  std::vector<double> cum_;  ///< cum_[i] = sum_{j<i} flux_j
  DetectorLaws laws_;
  uint64_t cycles_;
  int32_t K_;
  /// No avalanche after the cycle's last stop can change a later count: no
  /// afterpulses, no crosstalk sent, and no bin with flux whose dead time
  /// runs into the next cycle. Then the detector skips to the next pulse.
  bool quietAfterStops_;
  Moment liveFrom_;
  Event primary_;
  bool primaryValid_ = false;
  std::vector<Event> pending_;  ///< a min-heap on `at`
  uint64_t stopCycle_ = 0;
  int64_t stopsUsed_ = 0;
};

}  // namespace tofsim::sensors::detail
