#pragma once
// The CPU backend gathering the VPLs it is given instead of the RSM's (the
// later bounces the driver traces from them still follow): a gather of
// known VPLs, against a closed form.

#include <utility>
#include <vector>

#include "tofsim/cpu/CpuBackend.h"

namespace tofsim::test {

class GivenVplsCpuBackend : public cpu::CpuBackend {
 public:
  explicit GivenVplsCpuBackend(std::vector<ir::Vpl> vpls)
      : CpuBackend(cpu::CpuBackendOptions{2, true}), vpls_(std::move(vpls)) {}
  std::vector<ir::Vpl> generateVpls(const capture::RenderJob&) override { return vpls_; }

 private:
  std::vector<ir::Vpl> vpls_;
};

}  // namespace tofsim::test
