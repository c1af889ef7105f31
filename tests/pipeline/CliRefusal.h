#pragma once
// A config both `tofsim validate` and `tofsim render` refuse: exit 1 and
// `message` from each, nothing written to `out`. Returns what validate
// printed (for a caller's own checks, e.g. the error's line).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "pipeline/CliRun.h"

namespace tofsim::test {

inline CommandResult expectValidateAndRenderRefuse(const std::string& config,
                                                   const std::filesystem::path& out,
                                                   const std::string& message) {
  const CommandResult v = runCli("validate " + config);
  EXPECT_EQ(v.exitCode, 1) << v.output;
  EXPECT_NE(v.output.find(message), std::string::npos) << v.output;
  const CommandResult r = runCli("render -q " + config + " -o " + out.string());
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out)) << "render wrote " << out;
  return v;
}

}  // namespace tofsim::test
