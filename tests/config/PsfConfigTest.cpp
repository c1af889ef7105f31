// camera.psf: the parametric kernel and a kernel file become the kernel the
// pipeline applies, the effective config reloads to the same kernel, and bad
// values are errors at their key and line (a bad kernel value with its file
// and (y, x)).

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/io/Npy.h"

namespace tofsim::config {
namespace {

class PsfConfigTest : public test::TempDirTest {
 protected:
  RunConfig load(const std::string& psf) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    std::ofstream(dir_ / "c.yaml") << "scene: scene.gltf\ncamera:\n  resolution: [20, 12]\n"
                                   << "  psf: " << psf << "\nlight: {}\ntime: {}\n";
    return loadRunConfig(dir_ / "c.yaml");
  }
  std::string errorOf(const std::string& psf) {
    try {
      load(psf);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  void kernelFile(const std::string& name, const io::NpyShape& shape,
                  const std::vector<float>& values) {
    io::writeNpy(dir_ / name, shape, values.data());
  }
};

TEST_F(PsfConfigTest, ParametricKernelIsCroppedToTheImage) {
  const RunConfig c =
      load("{core_sigma: 0.5, halo_weight: 0.1, halo_profile: exponential, halo_radius: 3}");
  ASSERT_TRUE(c.camera.psf.has_value());
  const PsfConfig& p = *c.camera.psf;
  EXPECT_EQ(p.params.core_sigma_px, 0.5);
  EXPECT_EQ(p.params.halo_weight, 0.1);
  EXPECT_EQ(p.params.halo_profile, optics::HaloProfile::Exponential);
  EXPECT_EQ(p.params.halo_radius_px, 3.0);
  // 12 radii = 36 px, cropped to the 20-pixel image's largest offset, 19.
  EXPECT_EQ(p.kernel.radiusX(), 19);
  const optics::PsfKernel full = optics::PsfKernel::parametric(p.params);
  for (int d = -19; d <= 19; ++d) EXPECT_EQ(p.kernel.at(d, 2), full.at(d, 2));
  EXPECT_EQ(p.at.line, 4);                                // camera.psf, below camera.resolution
  EXPECT_TRUE(load("{}").camera.psf->kernel.identity());  // {}: a delta
}

TEST_F(PsfConfigTest, KernelFileRoundTrips) {
  kernelFile("k.npy", {3, 5}, {0, 1, 0, 0, 0, 1, 2, 12, 2, 1, 0, 0, 1, 0, 0});
  const RunConfig c = load("{file: k.npy}");
  ASSERT_TRUE(c.camera.psf.has_value());
  EXPECT_EQ(c.camera.psf->file, (dir_ / "k.npy").string());
  EXPECT_DOUBLE_EQ(c.camera.psf->kernel.at(0, 0), 12.0 / 20.0);
  EXPECT_DOUBLE_EQ(c.camera.psf->kernel.at(-1, -1), 1.0 / 20.0);
  const std::string written = effectiveConfigYaml(c);
  EXPECT_NE(written.find("file: " + (dir_ / "k.npy").string()), std::string::npos) << written;
  std::ofstream(dir_ / "again.yaml") << written;
  const RunConfig again = loadRunConfig(dir_ / "again.yaml");
  EXPECT_EQ(effectiveConfigYaml(again), written);
  EXPECT_EQ(again.camera.psf->kernel.image(), c.camera.psf->kernel.image());
}

TEST_F(PsfConfigTest, BadValuesAreLocatedErrors) {
  kernelFile("negative.npy", {3, 3}, {0, 1, 0, 1, 4, -0.25f, 0, 1, 0});
  kernelFile("even.npy", {3, 4}, std::vector<float>(12, 1.0f));
  kernelFile("dark.npy", {1, 1}, {0.0f});
  const struct {
    const char* psf;
    const char* fragment;
  } cases[] = {
      {"{file: negative.npy}", "camera.psf.file: "},
      {"{file: negative.npy}", "kernel value -0.25 at (y, x) = (1, 2) is negative"},
      {"{file: even.npy}", "a 3 x 4 (H x W) kernel; its sizes must be odd"},
      {"{file: dark.npy}", "must not all be 0"},
      {"{file: missing.npy}", "file not found"},
      {"{file: even.npy, halo_weight: 0.1}", "camera.psf.halo_weight: give a kernel file or"},
      {"{halo_weight: 1, halo_radius: 4}", "c.yaml:4"},
      {"{halo_weight: 1, halo_radius: 4}", "camera.psf.halo_weight: must be in [0, 1)"},
      {"{halo_weight: -0.01, halo_radius: 4}", "camera.psf.halo_weight: must be in [0, 1)"},
      {"{halo_weight: 0.1}", "camera.psf.halo_weight: a halo (halo_weight > 0) needs"},
      {"{halo_weight: 0.1, halo_radius: 0}", "camera.psf.halo_radius: a halo"},
      {"{core_sigma: -1}", "camera.psf.core_sigma: must be a finite number >= 0"},
      {"{halo_profile: lorentz}", "camera.psf.halo_profile: must be gaussian or exponential"},
      {"{halo_sigma: 3}", "halo_sigma"},
      {"3", "camera.psf: expected a mapping"},
  };
  for (const auto& k : cases) {
    const std::string e = errorOf(k.psf);
    EXPECT_NE(e.find(k.fragment), std::string::npos) << k.psf << " gave: " << e;
  }
}

}  // namespace
}  // namespace tofsim::config
