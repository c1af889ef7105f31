// The lens's PSF seen by a CW-ToF camera (camera.psf with a cwtof sensor),
// through runRender on the CPU backend: a bright near patch before a dark
// far wall. cwtof_psf_error on the wall is the phasor closed form: with a
// delta core and a halo of weight s, the wall pixel's phasor becomes
//   p'(x) = p(x) + s sum over x' of K_s(x - x') (p(x') - p(x)),
// p the sharp phasors (A e^(i phi) of the PSF-off run, noise-free), K_s the
// Gaussian halo in closed form; the patch's pixels give the classic
// p_wall + s S (p_patch - p_wall), the wall's own slow variation the rest
// (printed: the patch dominates). The raws path (the PSF on the sensor's
// charges) equals the transient path (the PSF on every bin) to float
// rounding; the path is chosen as PsfPath.h says; an identity PSF changes no
// byte and gives a zero error; without a PSF there is no cwtof_psf_error.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "support/AnalyticScenes.h"
#include "support/TempDir.h"
#include "tofsim/io/Exr.h"
#include "tofsim/io/Npy.h"
#include "tofsim/pipeline/PsfPath.h"
#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {
namespace {

using Complex = std::complex<double>;
namespace fs = std::filesystem;

constexpr int kSize = 32;
constexpr double kHaloWeight = 0.1, kHaloSigma_px = 2.0;
constexpr double kFrequency_Hz = 20e6;
constexpr double kC = 299792458.0;
const double kRange_m = kC / (2.0 * kFrequency_Hz);  // 7.49 m

std::string haloPsf(double s) {
  return ", psf: {halo_weight: " + std::to_string(s) +
         ", halo_profile: gaussian, halo_radius: " + std::to_string(kHaloSigma_px) + "}";
}

class CwTofPsfTest : public test::TempDirTest {
 protected:
  config::RunConfig config(const std::string& psf, const std::string& output = ", transient: false",
                           const std::string& sensor = "") {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    const std::string yaml =
        "scene: scene.gltf\n"
        "camera: {position: [0, 0, 2], look_at: [0, 0, 0], fov_y: 40 deg, resolution: [32, 32]" +
        psf +
        "}\n"
        "light: {attach_to_camera: true, intensity: 5}\n"
        "time: {start: 4 ns, bin_width: 50 ps, bins: 240}\n"
        "render: {backend: cpu, threads: 2, indirect: {enabled: false}}\n"
        "output: {steady: true, depth: true" +
        output +
        "}\n"
        "sensors:\n"
        "  - {type: cwtof, name: cwtof, frequencies: [\"20 MHz\"], phase_steps: 4, waveform: "
        "sine, channel_weights: [1, 1, 1], source_scale: 10000, ambient: 1000, shot_noise: false, "
        "read_noise: 0" +
        sensor + "}\n";
    return config::loadRunConfigText(yaml, dir_ / "c.yaml");
  }
  // A dark wall at 2 m filling the view, a bright square at 0.8 m.
  static scene::Scene scene() {
    scene::Scene s = test::makePlane(3.0f, glm::vec3(0.05f));
    test::addQuad(s, {0.0f, 0.0f, 1.2f}, {0.0f, 0.0f, 1.0f}, 0.06f, glm::vec3(0.9f));
    return s;
  }
  fs::path run(const config::RunConfig& c, const std::string& name, bool forceTransient = false) {
    RunOptions options;
    options.outputDirectory = dir_ / name;
    options.quiet = true;
    options.psfOnTransient = forceTransient;
    runRender(c, scene(), options);
    return dir_ / name;
  }
  static std::vector<float> image(const fs::path& dir, const std::string& name) {
    return io::readExr(dir / "sensors/cwtof" / (name + ".exr")).data;
  }
};

// The halo's pixel-integrated Gaussian profile, cut at ceil(5 sigma) and
// normalised (PsfKernel.h).
std::vector<double> haloProfile() {
  const int r = static_cast<int>(std::ceil(5.0 * kHaloSigma_px));
  std::vector<double> g(2 * r + 1);
  double sum = 0.0;
  for (int d = -r; d <= r; ++d) {
    const double k = 1.0 / (kHaloSigma_px * std::numbers::sqrt2);
    g[d + r] = 0.5 * (std::erf((d + 0.5) * k) - std::erf((d - 0.5) * k));
    sum += g[d + r];
  }
  for (double& v : g) v /= sum;
  return g;
}

double wrappedDepth_m(Complex p) {
  double phi = std::arg(p);
  if (phi < 0.0) phi += 2.0 * std::numbers::pi;
  return kRange_m * phi / (2.0 * std::numbers::pi);
}

double wrapSigned(double e) { return e - kRange_m * std::round(e / kRange_m); }

TEST_F(CwTofPsfTest, WallErrorIsThePhasorClosedFormOfTheHalo) {
  const fs::path sharp = run(config(""), "sharp");
  const fs::path blurred = run(config(haloPsf(kHaloWeight)), "blurred");
  EXPECT_FALSE(fs::exists(sharp / "sensors/cwtof/cwtof_psf_error.exr"));
  const std::vector<float> phase = image(sharp, "cwtof_phase_20MHz");
  const std::vector<float> amplitude = image(sharp, "cwtof_amplitude_20MHz");
  const std::vector<float> truth = io::readExr(sharp / "depth.exr").data;  // channels Y, Z
  const std::vector<float> error = image(blurred, "cwtof_psf_error");
  ASSERT_EQ(error.size(), std::size_t(kSize * kSize));
  std::vector<Complex> p(kSize * kSize);
  for (int i = 0; i < kSize * kSize; ++i) p[i] = std::polar(double(amplitude[i]), double(phase[i]));
  const std::vector<double> g = haloProfile();
  const int r = static_cast<int>(g.size() / 2);
  int patch = 0, wall = 0;
  double worst = 0.0, largest = 0.0, patchOnlyWorst = 0.0, wrongWeightWorst = 0.0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const int i = y * kSize + x;
      const double gt = truth[2 * i];
      if (gt < 1.5) ++patch;
      // Wall pixels whose halo stays in the image (nothing lost off it).
      if (gt < 1.5 || x < r || x >= kSize - r || y < r || y >= kSize - r) continue;
      ++wall;
      Complex fromPatch = 0.0, fromWall = 0.0;
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          const int j = (y - dy) * kSize + (x - dx);
          const Complex term = kHaloWeight * g[dx + r] * g[dy + r] * (p[j] - p[i]);
          (truth[2 * j] < 1.5 ? fromPatch : fromWall) += term;
        }
      }
      const double closedForm =
          wrapSigned(wrappedDepth_m(p[i] + fromPatch + fromWall) - wrappedDepth_m(p[i]));
      const double patchOnly = wrapSigned(wrappedDepth_m(p[i] + fromPatch) - wrappedDepth_m(p[i]));
      // The closed form of a halo weight 10 % higher (linear in s).
      const double wrongWeight =
          wrapSigned(wrappedDepth_m(p[i] + 1.1 * (fromPatch + fromWall)) - wrappedDepth_m(p[i]));
      worst = std::max(worst, std::abs(error[i] - closedForm));
      wrongWeightWorst = std::max(wrongWeightWorst, std::abs(error[i] - wrongWeight));
      patchOnlyWorst = std::max(patchOnlyWorst, std::abs(error[i] - patchOnly));
      largest = std::max(largest, std::abs(closedForm));
      // Stray light from the nearer patch pulls the wall nearer.
      if (std::abs(closedForm) > 1e-3) {
        EXPECT_LT(error[i], 0.0f) << x << ", " << y;
      }
    }
  }
  std::printf(
      "%d patch and %d wall pixels: largest error %.4f m, worst |error - closed form| %.2e m "
      "(patch term alone: %.2e m; a halo weight 10 %% off: %.2e m)\n",
      patch, wall, largest, worst, patchOnlyWorst, wrongWeightWorst);
  EXPECT_GE(patch, 4);
  EXPECT_GT(wall, 100);
  EXPECT_GT(largest, 0.05);  // decimetres: the effect is there
  // Float outputs (phase 2.4e-7 rad of 2 pi: 3e-7 m; the float volume):
  // 1e-5 m. A halo weight 10 % off is far outside it.
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(wrongWeightWorst, 1e-3);
}

TEST_F(CwTofPsfTest, TheRawsPathIsTheTransientPathToRounding) {
  const config::RunConfig c = config(haloPsf(kHaloWeight));
  ASSERT_EQ(choosePsfPath(c), PsfPath::Raws);
  ASSERT_EQ(choosePsfPath(c, true), PsfPath::Transient);
  const fs::path raws = run(c, "raws");
  const fs::path transient = run(c, "transient", true);
  for (const char* name : {"cwtof_depth", "cwtof_psf_error"}) {
    const std::vector<float> a = image(raws, name), b = image(transient, name);
    ASSERT_EQ(a.size(), b.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
      worst = std::max(worst, double(std::abs(a[i] - b[i])));
    std::printf("%s: worst |raws - transient| %.2e m\n", name, worst);
    EXPECT_LT(worst, 1e-5) << name;
  }
  const auto relative = [](const std::vector<float>& a, const std::vector<float>& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      worst =
          std::max(worst, std::abs(double(a[i]) - b[i]) / std::max(std::abs(double(b[i])), 1e-30));
    }
    return worst;
  };
  const io::NpyArray rawA = io::readNpy(raws / "sensors/cwtof/cwtof_raw.npy");
  const io::NpyArray rawB = io::readNpy(transient / "sensors/cwtof/cwtof_raw.npy");
  ASSERT_EQ(rawA.data.size(), rawB.data.size());
  const double rawWorst = relative(rawA.data, rawB.data);
  const std::vector<float> steadyA = io::readExr(raws / "steady.exr").data;
  const std::vector<float> steadyB = io::readExr(transient / "steady.exr").data;
  double steadyWorst = 0.0;
  float peak = 0.0f;
  for (float v : steadyB) peak = std::max(peak, v);
  for (std::size_t i = 0; i < steadyA.size(); ++i) {
    steadyWorst = std::max(steadyWorst, std::abs(double(steadyA[i]) - steadyB[i]) / peak);
  }
  std::printf("cwtof_raw: worst relative %.2e; steady: worst %.2e of its peak\n", rawWorst,
              steadyWorst);
  // The ambient (1000 e-) kept out of the blur: blurred, the border pixels
  // would lose ~1 % of it off the image.
  EXPECT_LT(rawWorst, 1e-5);
  EXPECT_LT(steadyWorst, 1e-5);
  const std::vector<float> truthA = io::readExr(raws / "depth.exr").data;
  EXPECT_EQ(truthA, io::readExr(transient / "depth.exr").data);  // the ground truth stays sharp
}

TEST_F(CwTofPsfTest, AnIdentityPsfChangesNoByteAndGivesNoError) {
  const fs::path off = run(config(""), "off");
  const fs::path identity = run(config(", psf: {}"), "identity", true);
  for (const char* file : {"cwtof_raw.npy", "cwtof_depth.exr", "cwtof_phase.npy"}) {
    std::ifstream a(off / "sensors/cwtof" / file, std::ios::binary);
    std::ifstream b(identity / "sensors/cwtof" / file, std::ios::binary);
    const std::string bytesA{std::istreambuf_iterator<char>(a), {}};
    const std::string bytesB{std::istreambuf_iterator<char>(b), {}};
    EXPECT_FALSE(bytesA.empty()) << file;
    EXPECT_EQ(bytesA, bytesB) << file;
  }
  for (float e : image(identity, "cwtof_psf_error")) EXPECT_EQ(e, 0.0f);
}

TEST_F(CwTofPsfTest, ThePathFallsBackToTheTransientWhereTheRawsAreNotExact) {
  const std::string psf = haloPsf(kHaloWeight);
  EXPECT_EQ(choosePsfPath(config("")), PsfPath::None);
  EXPECT_EQ(choosePsfPath(config(psf)), PsfPath::Raws);
  EXPECT_EQ(choosePsfPath(config(psf, ", transient: true")), PsfPath::Transient);
  EXPECT_EQ(choosePsfPath(config(psf, ", transient: false, components: [direct]")),
            PsfPath::Transient);
  EXPECT_EQ(choosePsfPath(config(psf, ", transient: false, frames: true")), PsfPath::Transient);
  EXPECT_EQ(choosePsfPath(config(psf, "", ", delay_sigma: 10 ps")), PsfPath::Transient);
}

}  // namespace
}  // namespace tofsim::pipeline
