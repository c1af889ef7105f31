// A preset's capture order carried over to other frequencies and steps
// (sensors/CwTofCaptureOrder.h): Kinect's descending steps on new counts,
// ascending and permuted blocks, and the patterns the rule cannot carry.

#include "tofsim/sensors/CwTofCaptureOrder.h"

#include <gtest/gtest.h>

namespace tofsim::sensors {
namespace {

using Order = std::vector<CwTofCaptureStep>;

// Kinect v2's: 3 frequencies in index order, steps 0, 2, 1 each.
const Order kKinect{{0, 0}, {0, 2}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {2, 0}, {2, 2}, {2, 1}};

TEST(CwTofCaptureOrderTest, KinectsPatternCarriesOverToNewFrequenciesAndSteps) {
  EXPECT_EQ(deriveCwTofCaptureOrder(kKinect, 3, 3, 3, 3), kKinect);
  EXPECT_EQ(deriveCwTofCaptureOrder(kKinect, 3, 3, 2, 3),
            (Order{{0, 0}, {0, 2}, {0, 1}, {1, 0}, {1, 2}, {1, 1}}));
  EXPECT_EQ(deriveCwTofCaptureOrder(kKinect, 3, 3, 1, 4), (Order{{0, 0}, {0, 3}, {0, 2}, {0, 1}}));
  EXPECT_EQ(cwtofCaptureOrderText(*deriveCwTofCaptureOrder(kKinect, 3, 3, 1, 2)),
            "[[0, 0], [0, 1]]");
}

TEST(CwTofCaptureOrderTest, ABlockOrderCarriesOverOnlyToItsOwnCount) {
  const Order reversed{{1, 0}, {1, 1}, {0, 0}, {0, 1}};
  EXPECT_EQ(deriveCwTofCaptureOrder(reversed, 2, 2, 2, 3),
            (Order{{1, 0}, {1, 1}, {1, 2}, {0, 0}, {0, 1}, {0, 2}}));
  EXPECT_FALSE(deriveCwTofCaptureOrder(reversed, 2, 2, 3, 2));
}

TEST(CwTofCaptureOrderTest, PatternsTheRuleCannotCarryAreRefused) {
  // Step-major (not frequency-major), one step order per frequency, a step
  // order neither ascending nor descending from 0 on a new count.
  const Order stepMajor{{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  const Order twoStepOrders{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  const Order shuffled{{0, 1}, {0, 0}, {0, 2}};
  EXPECT_FALSE(deriveCwTofCaptureOrder(stepMajor, 2, 2, 3, 2));
  EXPECT_FALSE(deriveCwTofCaptureOrder(twoStepOrders, 2, 2, 3, 2));
  EXPECT_FALSE(deriveCwTofCaptureOrder(shuffled, 1, 3, 1, 4));
  EXPECT_EQ(deriveCwTofCaptureOrder(shuffled, 1, 3, 2, 3),
            (Order{{0, 1}, {0, 0}, {0, 2}, {1, 1}, {1, 0}, {1, 2}}));
  EXPECT_FALSE(deriveCwTofCaptureOrder(kKinect, 3, 2, 3, 3));  // not 3 x 2 raws
}

}  // namespace
}  // namespace tofsim::sensors
