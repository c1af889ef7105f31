#include "GatherResponseClasses.h"

#include "GpuContract.h"

namespace tofsim::render {

GatherResponseClasses::GatherResponseClasses(const physics::ResponseClassTable& table) {
  if (!table.delayed()) return;
  defines_ = {{"RESPONSE_CLASSES", "1"},
              {"RESPONSE_KERNEL_COUNT", std::to_string(table.kernels.size())}};
  compose_ = gl::Buffer(table.compose.size() * sizeof(uint32_t), table.compose.data(), 0);
}

void GatherResponseClasses::bind() const {
  if (delayed()) compose_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kResponseCompose);
}

void GatherResponseClasses::setRegionPixels(const gl::Program& gather,
                                            std::size_t regionPixels) const {
  if (delayed()) gather.set("uResponseRegionPixels", static_cast<unsigned>(regionPixels));
}

}  // namespace tofsim::render
