#include "SpadEventEngine.h"

#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

void spadEvents(const std::vector<double>& flux, uint64_t cycles, const DetectorLaws& laws,
                Rng& rng, std::vector<double>& h) {
  TOFSIM_CHECK(!flux.empty() && h.size() == flux.size());
  SpadDetector detector(flux, laws, cycles);
  for (;;) {
    const Event e = detector.next(rng);
    if (!(e.at.cycle < cycles)) break;
    detector.fire(e, rng, h);
  }
}

}  // namespace tofsim::sensors::detail
