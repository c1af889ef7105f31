#pragma once
// The gathers' side of the response classes on GL (issue 41,
// core/physics/temporal_response.md): for a render whose table has delayed
// classes, the gathers' defines (RESPONSE_CLASSES, RESPONSE_KERNEL_COUNT),
// the table's `compose` as the buffer response_classes.glsl reads, and the
// region size depositDelayed addresses classes by. A render without delayed
// classes has none of them: its gathers compile and run as before.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "tofsim/gl/Buffer.h"
#include "tofsim/gl/Program.h"
#include "tofsim/physics/ResponseClassTable.h"

namespace tofsim::render {

class GatherResponseClasses {
 public:
  GatherResponseClasses() = default;
  /// Uploads the table's compose where it has delayed classes.
  explicit GatherResponseClasses(const physics::ResponseClassTable& table);

  bool delayed() const { return !defines_.empty(); }
  /// The gathers' defines: none without delayed classes.
  const std::vector<std::pair<std::string, std::string>>& defines() const { return defines_; }
  /// Binds the compose buffer for a gather (no-op without delayed classes).
  void bind() const;
  /// Sets a gather's uResponseRegionPixels: pixels per class region of the
  /// footprint buffer (PixelFootprint::regionPixels).
  void setRegionPixels(const gl::Program& gather, std::size_t regionPixels) const;
  std::size_t bytes() const { return compose_.size(); }

 private:
  std::vector<std::pair<std::string, std::string>> defines_;
  gl::Buffer compose_;
};

}  // namespace tofsim::render
