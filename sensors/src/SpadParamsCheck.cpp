#include "SpadParamsCheck.h"

#include "SpadExactCrosstalk.h"
#include "tofsim/util/Error.h"

namespace tofsim::sensors::detail {

void checkSpadParams(const SpadParams& p) {
  TOFSIM_CHECK(p.cycles >= 1);
  TOFSIM_CHECK(p.pulse_fwhm_s >= 0.0 && p.jitter_fwhm_s >= 0.0 && p.jitter_tail_s >= 0.0);
  TOFSIM_CHECK(p.jitter_tail_fraction >= 0.0 && p.jitter_tail_fraction <= 1.0);
  TOFSIM_CHECK(p.pde >= 0.0 && p.pde <= 1.0);
  TOFSIM_CHECK(p.ambient_rate_per_s >= 0.0 && p.dark_count_rate_per_s >= 0.0);
  TOFSIM_CHECK(p.dead_time_s >= 0.0 && p.tdc_stops >= 0);
  TOFSIM_CHECK(p.gate_width_s >= 0.0 && p.gate_skew_sigma_s >= 0.0);
  TOFSIM_CHECK(p.gated_frames >= 0 && p.pulses_per_frame >= 1 && p.gate_positions >= 1);
  TOFSIM_CHECK(p.counter_bits >= 0 && p.counter_bits <= kMaxCounterBits);
  TOFSIM_CHECK(p.afterpulse_probability >= 0.0 && p.afterpulse_probability <= 1.0);
  TOFSIM_CHECK(!p.afterpulse_delays_s.empty());
  for (double d : p.afterpulse_delays_s) TOFSIM_CHECK(d > 0.0);
  TOFSIM_CHECK(p.afterpulse_weights.empty() ||
               p.afterpulse_weights.size() == p.afterpulse_delays_s.size());
  if (p.afterpulse_delay_table.present()) {
    const SpadAfterpulseTable& t = p.afterpulse_delay_table;
    TOFSIM_CHECK(t.delays_s.size() >= 2 && t.density_per_s.size() == t.delays_s.size() &&
                 t.edges_s.size() == t.delays_s.size() + 1);
  }
  TOFSIM_CHECK(p.crosstalk_probability >= 0.0 && p.crosstalk_probability <= 1.0);
  TOFSIM_CHECK(p.crosstalk_delay_s >= 0.0);
  // A delayed arrival into a gate, gate ramps or per-pixel skew: the exact
  // array driver only (config errors with `engine: fast`); the gated frames'
  // other gate positions: not modelled (checkCrosstalkGate).
  TOFSIM_CHECK(p.engine != SpadEngine::Fast || !crosstalkNeedsEvents(p));
  TOFSIM_CHECK(p.crosstalk_probability == 0.0 || p.gated_frames == 0);
  if (p.irf.present()) {
    TOFSIM_CHECK(p.irf.sample_width_s > 0.0);
    TOFSIM_CHECK(p.pulse_fwhm_s == 0.0 && p.jitter_fwhm_s == 0.0 && p.jitter_tail_fraction == 0.0);
  }
  TOFSIM_CHECK(p.pde_spread >= 0.0 && p.dark_count_log_sigma >= 0.0);
  TOFSIM_CHECK(p.hot_pixel_fraction >= 0.0 && p.hot_pixel_fraction <= 1.0);
  TOFSIM_CHECK(p.dead_pixel_fraction >= 0.0 && p.dead_pixel_fraction <= 1.0);
  TOFSIM_CHECK(p.hot_pixel_rate_per_s >= 0.0);
  TOFSIM_CHECK(p.return_threshold_sigma > 0.0);
}

}  // namespace tofsim::sensors::detail
