#pragma once
// The white point of the tone maps: the 99.5th percentile of the positive
// finite values, from at most ~4M evenly spaced samples (exact enough for a
// display scale, without copying a whole volume). Fed in pieces, in order, it
// takes the same samples as from the whole array at once, so a volume that
// streams past (the video's, segment by segment) gets the same white.

#include <cstddef>
#include <vector>

namespace tofsim::imaging {

class WhiteLevelSampler {
 public:
  /// `count`: the number of values that will be fed in all.
  explicit WhiteLevelSampler(std::size_t count);
  /// The next `n` values of the array.
  void add(const float* values, std::size_t n);
  /// The percentile of the samples; 1 when none is positive. After every value.
  double white();

 private:
  std::size_t step_ = 1;
  std::size_t next_ = 0;  ///< index of the next sample in the whole array
  std::size_t fed_ = 0;   ///< values fed so far
  std::vector<float> samples_;
};

}  // namespace tofsim::imaging
