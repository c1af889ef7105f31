// Issue 39: every blur kernel a sensor builds (a SPAD's measured IRF or its
// pulse, jitter and tail, its delayed crosstalk; a streak camera's time and
// space blurs) is checked where the config is read, against the bins it is
// laid out on, so that `validate`, `render` and `sense` give a located error
// instead of a CHECK abort in TimeKernel.cpp; and an IRF's t0 must lie within
// the response it names.
#include <fstream>
#include <string>

#include "SensorKeysTest.h"
#include "tofsim/sensors/Spad.h"
#include "tofsim/sensors/Streak.h"

namespace tofsim::config {
namespace {

constexpr const char* kRun = R"(scene: scene.gltf
camera: {resolution: [4, 4]}
light: {}
time: {start: 1 ns, bin_width: 10 ps, bins: 100}
sensors:
)";

class TimeKernelConfigTest : public test::RunSensorKeysTest<sensors::SpadParams> {
 protected:
  TimeKernelConfigTest() : RunSensorKeysTest(kRun) {}
  void expectError(const std::string& keys, const std::string& key, const std::string& words) {
    const std::string message = errorOf(keys);
    EXPECT_NE(message.find("test.yaml:"), std::string::npos) << message;
    EXPECT_NE(message.find("sensors[0]." + key + ": "), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  }
  void writeIrf(const std::string& name, const std::string& rows) {
    std::ofstream(dir_ / name) << "time_s,value\n" << rows;
  }
};

TEST_F(TimeKernelConfigTest, IrfTimeZeroOutsideTheResponseIsALocatedError) {
  writeIrf("irf.csv", "0,1\n2e-12,3\n4e-12,1\n");
  const std::string spad = "  - type: spad\n    irf: {file: irf.csv, t0: ";
  // Within the response's span [-1 ps, 5 ps] (the samples' edges): fine.
  EXPECT_NO_THROW(load(spad + "4.9 ps}\n"));
  EXPECT_NO_THROW(load(spad + "-0.9 ps}\n"));
  for (const std::string t0 : {"1 s", "-1 s", "6 ps"}) {
    SCOPED_TRACE(t0);
    expectError(spad + t0 + "}\n", "irf.t0", "lies outside the response in");
  }
  expectError(spad + "1 s}\n", "irf.t0", "which spans [-1 ps, ");
}

TEST_F(TimeKernelConfigTest, IrfSpanningMoreBinsThanAKernelHoldsIsALocatedError) {
  // Times in the wrong unit: 3 samples 1e30 s apart, on 10 ps bins.
  writeIrf("wide.csv", "0,1\n1e30,2\n2e30,1\n");
  expectError("  - type: spad\n    irf: {file: wide.csv}\n", "irf.file",
              "wide.csv: the response (3 samples 1e+30 s apart) reaches");
  expectError("  - type: spad\n    irf: {file: wide.csv}\n", "irf.file",
              "a blur kernel reaches at most 4194304 bins");
}

TEST_F(TimeKernelConfigTest, PulseJitterTailAndCrosstalkKernelsAreBounded) {
  const std::string spad = "  - type: spad\n";
  expectError(spad + "    jitter_fwhm: 1 s\n", "jitter_fwhm", "bins of 1e-11 s");
  expectError(spad + "    pulse_fwhm: 1 s\n", "pulse_fwhm", "from zero delay");
  expectError(spad + "    jitter_tail_fraction: 0.1\n    jitter_tail: 1 s\n", "jitter_tail",
              "at most 4194304 bins");
  expectError(spad + "    crosstalk_probability: 0.1\n    crosstalk_delay: 1 s\n",
              "crosstalk_delay", "at most 4194304 bins");
  // The SPAD's own coarser bins decide: 1 ms of jitter on 1 ns bins fits.
  EXPECT_NO_THROW(load(spad + "    bin_width: 1 ns\n    jitter_fwhm: 1 ms\n"));
}

TEST_F(TimeKernelConfigTest, StreakBlursAreBounded) {
  const std::string streak = "  - type: streak\n";
  expectError(streak + "    time_fwhm: 1 s\n", "time_fwhm", "bins of 1e-11 s");
  expectError(streak + "    spatial_fwhm: 1e30\n", "spatial_fwhm", "bins of 1 px");
}

TEST_F(TimeKernelConfigTest, AnIrfPathThatIsAFolderSaysSo) {
  std::filesystem::create_directory(dir_ / "irf_folder.csv");
  expectError("  - type: spad\n    irf: {file: irf_folder.csv}\n", "irf.file",
              "is a folder, not a file (IRF file)");
  expectError("  - type: spad\n    tdc_dnl: irf_folder.csv\n", "tdc_dnl", "is a folder");
  expectError("  - type: spad\n    irf: {file: absent.csv}\n", "irf.file", "IRF file not found");
}

}  // namespace
}  // namespace tofsim::config
