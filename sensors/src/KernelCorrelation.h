#pragma once
// Private to the SPAD model: a histogram correlated with two kernels at once,
// the inner loop of the log-matched filter (SpadEstimators.h).

#include <cstdint>
#include <vector>

namespace tofsim::sensors::detail {

/// For tau in [0, h.size()): ca[tau] = sum_j h[tau + first + j] a[j] and
/// cb[tau] likewise with b (a.size() == b.size(); bins outside h count 0).
/// Each sum runs over j ascending, i.e. over the bins of h in order, and the
/// terms of bins with h == 0 (+0, the kernels are >= 0) change nothing: the
/// same doubles however it is computed. Dense histograms by blocks of
/// arrival bins (their sums in registers, vectorised); sparse ones from
/// each counted bin. `padded` is scratch. `portable`: not the AVX2 version
/// of the blocks even where the CPU has AVX2 (for the tests: the same bits).
void correlateWithTwo(const std::vector<double>& h, int32_t first, const std::vector<double>& a,
                      const std::vector<double>& b, std::vector<double>& ca,
                      std::vector<double>& cb, std::vector<double>& padded, bool portable = false);

}  // namespace tofsim::sensors::detail
