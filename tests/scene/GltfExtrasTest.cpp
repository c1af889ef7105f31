// A glTF material's `extras` reach the document as scalars by path
// (MaterialDesc::extras): the per-material parameters the scene reads by name
// (issue 41: a material's scattering delay from its extras), an array's
// elements by index. Nulls and other materials' extras stay out.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "GltfTestFiles.h"
#include "TinyGltfImport.h"
#include "support/TempDir.h"

namespace tofsim::scene {
namespace {

class GltfExtrasTest : public test::TempDirTest {};

TEST_F(GltfExtrasTest, MaterialExtrasAreScalarsByPath) {
  const auto path = test::writeText(dir_ / "e.gltf", test::triangleGltf(R"("nodes": [{"mesh": 0}],
      "scenes": [{"nodes": [0]}],
      "materials": [
        {"name": "plain"},
        {"name": "wax", "extras": {"albedo_scale": 0.5, "label": "x", "ok": true,
                                   "list": [1, 2], "nothing": null,
                                   "scattering_delay": {"model": "exponential",
                                                        "lifetime": 2.5e-9,
                                                        "fraction": 0.6}}}])"));
  const detail::GltfDocument doc = detail::importGltf(path);
  ASSERT_EQ(doc.materials.size(), 2u);
  EXPECT_TRUE(doc.materials[0].extras.empty());
  const std::map<std::string, std::string> expected = {
      {"albedo_scale", "0.5"},
      {"label", "x"},
      {"list.0", "1"},
      {"list.1", "2"},
      {"ok", "true"},
      {"scattering_delay.fraction", "0.59999999999999998"},
      {"scattering_delay.lifetime", "2.5000000000000001e-09"},
      {"scattering_delay.model", "exponential"}};
  EXPECT_EQ(doc.materials[1].extras, expected);
  // The text holds the double exactly.
  EXPECT_EQ(std::stod(doc.materials[1].extras.at("scattering_delay.lifetime")), 2.5e-9);
}

}  // namespace
}  // namespace tofsim::scene
