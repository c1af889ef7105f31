// The CW-ToF multipath error by bounce order end to end (sensors/README.md,
// "Multipath error by bounce order"): the corner of configs/cwtof_corner.yaml
// rendered with 3 bounces on the CPU backend. Order 3 is the whole light, so
// it equals cwtof_mpi_error; each order adds later light, so on this concave
// corner the mean error grows with the order; the bytes repeat, and
// `tofsim sense` on the saved folder reproduces them from bounce<k>.npy.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/CliRun.h"
#include "support/TempDir.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"

namespace tofsim {
namespace {

using test::CommandResult;

const std::string kCorner = std::string(TOFSIM_SOURCE_DIR) + "/configs/cwtof_corner.yaml";
const std::string kSmall =
    " --set camera.resolution=[16,16] --set render.indirect.rsm_resolution=8"
    " --set render.indirect.points_per_vpl=200 --set sensors.0.multipath_by_order=true";
const std::string kThreeBounces =
    kSmall +
    " --set render.indirect.bounces=3 --set output.components=[direct,bounce1,bounce2,bounce3]";

class MultipathByOrderCliTest : public test::TempDirTest {
 protected:
  std::filesystem::path sensorFile(const std::string& run, const std::string& name) const {
    return dir_ / run / "sensors" / "cwtof" / name;
  }
  CommandResult render(const std::string& run, const std::string& args) const {
    return test::runCli("render " + kCorner + " -q --backend cpu -o " + (dir_ / run).string() +
                        args);
  }
};

// Mean of the finite values of order k of a (orders, H, W) array.
double meanOfOrder(const io::NpyArray& a, std::size_t k) {
  const std::size_t plane = a.shape[1] * a.shape[2];
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = k * plane; i < (k + 1) * plane; ++i) {
    if (std::isfinite(a.data[i])) {
      sum += a.data[i];
      ++n;
    }
  }
  return n ? sum / static_cast<double>(n) : NAN;
}

TEST_F(MultipathByOrderCliTest, LastOrderIsTheMultipathErrorAndOrdersAddLaterLight) {
  const CommandResult r = render("a", kThreeBounces);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const io::NpyArray byOrder = io::readNpy(sensorFile("a", "cwtof_multipath_error_by_order.npy"));
  ASSERT_EQ(byOrder.shape, (io::NpyShape{4, 16, 16}));
  const Image mpi = io::readExr(sensorFile("a", "cwtof_mpi_error.exr"));
  const std::size_t plane = 16 * 16;
  std::size_t compared = 0;
  for (std::size_t px = 0; px < plane; ++px) {
    const float last = byOrder.data[3 * plane + px], whole = mpi.data[px];
    if (!std::isfinite(whole)) continue;
    ASSERT_TRUE(std::isfinite(last)) << px;
    EXPECT_NEAR(last, whole, 1e-5) << px;  // the float sum of the components vs their correlations
    ++compared;
  }
  EXPECT_GT(compared, plane / 2);
  // Every return after the direct one arrives later: each order lengthens the
  // depth on average, by less as the bounces weaken.
  const double e[4] = {meanOfOrder(byOrder, 0), meanOfOrder(byOrder, 1), meanOfOrder(byOrder, 2),
                       meanOfOrder(byOrder, 3)};
  EXPECT_LT(std::fabs(e[0]), 0.01) << "direct light only";
  for (int k = 1; k < 4; ++k) EXPECT_GT(e[k], e[k - 1]) << k;
  EXPECT_GT(e[1] - e[0], e[2] - e[1]);
  EXPECT_GT(e[2] - e[1], e[3] - e[2]);
  for (int k = 0; k < 4; ++k) {
    EXPECT_TRUE(std::filesystem::exists(
        sensorFile("a", "cwtof_multipath_error_order" + std::to_string(k) + ".png")));
  }
  EXPECT_TRUE(std::filesystem::exists(sensorFile("a", "cwtof_multipath_error_by_order.json")));

  // Determinism, and `tofsim sense` from the saved bounce<k>.npy.
  ASSERT_EQ(render("b", kThreeBounces).exitCode, 0);
  const std::string name = "cwtof_multipath_error_by_order.npy";
  EXPECT_EQ(test::fileBytes(sensorFile("a", name)), test::fileBytes(sensorFile("b", name)));
  const CommandResult s =
      test::runCli("sense " + kCorner + " -q --volume " + (dir_ / "a").string() + " -o " +
                   (dir_ / "s").string() + kThreeBounces);
  ASSERT_EQ(s.exitCode, 0) << s.output;
  EXPECT_EQ(test::fileBytes(sensorFile("a", name)), test::fileBytes(sensorFile("s", name)));
}

TEST_F(MultipathByOrderCliTest, DirectOnlyOrderOfAPlaneIsZeroWithinTheSensorsPrecision) {
  // Indirect light off: one order, the direct light of the corner's planes,
  // with the light at the pinhole (an offset light's path is not twice the
  // depth). All of a pixel's light in its centre's bin: off by at most half
  // a 20 ps bin of depth, c 20 ps / 4 = 1.499 mm. The pixel footprint spreads
  // it over the bins symmetrically about the centre's path: 1.6e-5 m here.
  for (const auto& [footprint, bound_m] : {std::pair{"false", 1.5e-3}, std::pair{"true", 5e-5}}) {
    const std::string run = std::string("d") + footprint;
    const CommandResult r =
        render(run, kSmall + " --set render.indirect.enabled=false --set light.offset=[0,0,0]" +
                        " --set render.pixel_footprint=" + footprint);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const io::NpyArray e = io::readNpy(sensorFile(run, "cwtof_multipath_error_by_order.npy"));
    ASSERT_EQ(e.shape, (io::NpyShape{1, 16, 16}));
    for (float v : e.data) {
      ASSERT_TRUE(std::isfinite(v));  // every pixel sees a lit wall
      EXPECT_LT(std::fabs(v), bound_m) << "pixel_footprint " << footprint;
    }
  }
}

TEST_F(MultipathByOrderCliTest, SenseWithoutTheBounceFilesNamesTheMissingOne) {
  ASSERT_EQ(render("n", kThreeBounces + " --set output.components=[direct,bounce1]").exitCode, 0);
  const CommandResult s =
      test::runCli("sense " + kCorner + " -q --volume " + (dir_ / "n").string() + " -o " +
                   (dir_ / "s").string() + kThreeBounces);
  EXPECT_NE(s.exitCode, 0) << s.output;
  EXPECT_NE(s.output.find("bounce2.npy: not found"), std::string::npos) << s.output;
  EXPECT_NE(s.output.find("indirect_bounces 3"), std::string::npos) << s.output;
}

TEST_F(MultipathByOrderCliTest, ReferenceWithMoreThanOneBounceIsALocatedError) {
  const CommandResult r =
      render("r", kSmall + " --set render.renderer=reference --set render.reference.bounces=3");
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("sensors[0].multipath_by_order"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("render.reference.bounces: 3"), std::string::npos) << r.output;
  const CommandResult d = render("r", kSmall + " --set output.depth=false");
  EXPECT_NE(d.exitCode, 0) << d.output;
  EXPECT_NE(d.output.find("output.depth: true"), std::string::npos) << d.output;
}

}  // namespace
}  // namespace tofsim
