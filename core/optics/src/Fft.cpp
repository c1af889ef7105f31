#include "tofsim/optics/Fft.h"

#include "Fft2d.h"
#include "tofsim/util/Error.h"

namespace tofsim::optics {

void fourierTransform(std::vector<std::complex<double>>& data) {
  TOFSIM_CHECK(data.size() <= (std::size_t{1} << 30));
  Fft2d(static_cast<int32_t>(data.size()), 1).forward(data.data());
}

int powerOfTwoAtLeast(int n) { return Fft2d::powerOfTwoAtLeast(n); }

}  // namespace tofsim::optics
