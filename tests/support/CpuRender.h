#pragma once
// A render on the CPU IR backend through the one IR driver, as `tofsim
// render` with render.backend=cpu runs it, into memory: the volumes and what
// the driver reports. Links no GL (the tests/cpu programs without "GL" in
// their names must not).

#include <memory>

#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/cpu/CpuBackend.h"
#include "tofsim/ir/IrRenderer.h"

namespace tofsim::test {

struct CpuRender {
  capture::VolumeCollector volume;
  capture::RenderResult result;
};

inline CpuRender renderOnCpu(const capture::RenderJob& job,
                             const cpu::CpuBackendOptions& options = {2, true}) {
  CpuRender out{
      capture::VolumeCollector(capture::imageWidth(job.imager), capture::imageHeight(job.imager),
                               job.settings.time, capture::kChannels),
      {}};
  out.result = ir::IrRenderer(std::make_unique<cpu::CpuBackend>(options)).render(job, out.volume);
  return out;
}

}  // namespace tofsim::test
