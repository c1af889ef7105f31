// Configs and sensors from text (what the Python module hands over), and
// integer keys given as integral floats (`cycles: 1e5`).

#include <gtest/gtest.h>

#include <fstream>
#include <variant>

#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/config/SensorConfig.h"
#include "tofsim/util/Error.h"

namespace tofsim::config {
namespace {

class TextConfigTest : public test::TempDirTest {
 protected:
  std::string config(const std::string& extra) {
    std::ofstream(dir_ / "scene.gltf") << "{}";
    return "scene: " + (dir_ / "scene.gltf").string() + "\ncamera: {}\nlight: {}\ntime:\n" + extra;
  }
};

InputError errorOf(const std::string& text, const std::string& file) {
  try {
    loadRunConfigText(text, file);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError("");
}

TEST_F(TextConfigTest, TextLoadsAsAFileDoes) {
  const RunConfig c = loadRunConfigText(config("  bins: 64\n"), "<string>", {{"time.bins", "32"}});
  EXPECT_EQ(c.render.time.bins, 32);
  EXPECT_EQ(c.config_file, "<string>");
  const InputError e = errorOf(config("  bins: 64\n  bin_width: -1 ps\n"), "<string>");
  EXPECT_EQ(e.location().file, "<string>");
  EXPECT_EQ(e.location().line, 6);
  EXPECT_EQ(e.key(), "time.bin_width");
}

TEST_F(TextConfigTest, IntegerKeysTakeIntegralFloatsOnly) {
  EXPECT_EQ(loadRunConfigText(config("  bins: 1e3\n"), "<string>").render.time.bins, 1000);
  EXPECT_EQ(loadRunConfigText(config("  bins: 64.0\n"), "<string>").render.time.bins, 64);
  for (const char* bad : {"  bins: 64.5\n", "  bins: 1e-3\n", "  bins: 1e400\n", "  bins: 6x\n"}) {
    const InputError e = errorOf(config(bad), "<string>");
    EXPECT_EQ(e.key(), "time.bins") << bad;
    EXPECT_NE(std::string(e.what()).find("expected an integer"), std::string::npos) << e.what();
  }
}

// YAML lets any node be a mapping key (`? [a, b]: 1`); a config key is a name.
// The fuzzer found the unread-key check aborting on one (CI, fuzz_config).
TEST_F(TextConfigTest, KeysThatAreNotNamesAreLocatedErrors) {
  struct Case {
    std::string extra;
    std::string key;
    int line;
  };
  const Case cases[] = {
      {"  bins: 8\n? [a, b]: 1\n", "", 6},
      {"  bins: 8\n  ? {x: 1}: 2\n", "time", 6},
      {"  bins: 8\n? position: [0.3, 0.5]\n", "", 6},
      {"  bins: 8\noutput:\n  plot_ranges:\n    ? [depth]: [0, 1]\n", "output.plot_ranges", 8},
      {"  bins: 8\nsensors:\n  - {type: spad, ? [pde]: 0.5}\n", "sensors[0]", 7},
  };
  for (const Case& c : cases) {
    const InputError e = errorOf(config(c.extra), "<string>");
    EXPECT_EQ(e.key(), c.key) << c.extra;
    EXPECT_EQ(e.location().line, c.line) << c.extra;
    EXPECT_NE(std::string(e.what()).find("a key must be a plain name"), std::string::npos)
        << e.what();
  }
}

// A plot range named without a value read past an empty list (a segfault in
// `validate`; found by fuzz_sequence, tests/regressions/sequence/).
TEST_F(TextConfigTest, PlotRangeWithoutAValueIsALocatedError) {
  const InputError e =
      errorOf(config("  bins: 8\noutput:\n  plot_ranges:\n    depth:\n"), "<string>");
  EXPECT_EQ(e.key(), "output.plot_ranges.depth");
  EXPECT_NE(std::string(e.what()).find("got nothing"), std::string::npos) << e.what();
}

TEST_F(TextConfigTest, SensorTextParsesOneSensorWithLocatedErrors) {
  const sensors::SensorSpec spec =
      parseSensorText(R"({"type": "spad", "cycles": 100000.0, "pde": 0.5})", "<sensor>");
  const auto& spad = std::get<sensors::SpadParams>(spec.params);
  EXPECT_EQ(spad.cycles, 100000);
  EXPECT_DOUBLE_EQ(spad.pde, 0.5);
  EXPECT_EQ(spec.name, "spad");
  try {
    parseSensorText(R"({"type": "spad", "pdee": 0.5})", "<sensor>");
    ADD_FAILURE() << "unknown key accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "sensors[0].pdee");
    EXPECT_EQ(e.location().file, "<sensor>");
  }
}

}  // namespace
}  // namespace tofsim::config
