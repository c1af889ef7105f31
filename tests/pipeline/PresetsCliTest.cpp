// `tofsim presets` lists every device preset with the values it sets and
// their sources, without an error to provoke; `tofsim --help` and each
// subcommand's help point to the docs and a first config (issue 44, item 11).

#include <gtest/gtest.h>

#include <string>

#include "pipeline/CliRun.h"
#include "tofsim/config/LidarPresets.h"
#include "tofsim/sensors/CwTofPresets.h"
#include "tofsim/sensors/SpadPresets.h"

namespace tofsim::test {
namespace {

template <class Params>
void expectListed(const sensors::DevicePreset<Params>& preset, const std::string& out) {
  const std::string head = std::string(preset.name) + " (";
  const std::size_t at = out.find(head);
  ASSERT_NE(at, std::string::npos) << preset.name;
  for (const sensors::PresetValue& v : preset.values) {
    const std::string line = std::string("  ") + v.key + " = ";
    const std::size_t key = out.find(line, at);
    ASSERT_NE(key, std::string::npos) << preset.name << " " << v.key;
    const std::string rest = out.substr(key, out.find('\n', key) - key);
    EXPECT_EQ(rest.find("(set)"), std::string::npos) << rest;  // a value, not a placeholder
    const std::string why = v.source ? v.source : v.note;
    EXPECT_NE(rest.find(why), std::string::npos) << rest;
  }
  for (const char* s : preset.sources) EXPECT_NE(out.find(s, at), std::string::npos) << s;
}

TEST(PresetsCliTest, ListsEveryPresetWithValuesAndSources) {
  const CommandResult r = runCli("presets");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const auto& p : sensors::spadPresets()) expectListed(p, r.output);
  for (const auto& p : sensors::cwtofPresets()) expectListed(p, r.output);
  for (const auto& p : config::lidarPresets()) expectListed(p, r.output);
  EXPECT_NE(r.output.find("spad512s (spad)"), std::string::npos);
  EXPECT_NE(r.output.find("bin_width = 1.7e-11 s"), std::string::npos) << r.output;  // 17 ps, s

  const CommandResult one = runCli("presets spad512s");
  ASSERT_EQ(one.exitCode, 0) << one.output;
  EXPECT_EQ(one.output.find("kinect-v2"), std::string::npos);
  const CommandResult none = runCli("presets spad513");
  EXPECT_EQ(none.exitCode, 1);
  EXPECT_NE(none.output.find("no preset 'spad513' (presets: "), std::string::npos) << none.output;
}

TEST(PresetsCliTest, HelpPointsToTheDocsAndAnExample) {
  for (const std::string args : {"--help", "render --help", "validate --help", "presets --help"}) {
    const CommandResult r = runCli(args);
    EXPECT_EQ(r.exitCode, 0) << args;
    EXPECT_NE(r.output.find("configs/README.md"), std::string::npos) << args << r.output;
    EXPECT_NE(r.output.find("README.md (quick start"), std::string::npos) << args;
    EXPECT_NE(r.output.find("tofsim render configs/cornell_box.yaml"), std::string::npos) << args;
  }
}

}  // namespace
}  // namespace tofsim::test
