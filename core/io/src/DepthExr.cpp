#include "tofsim/io/DepthExr.h"

#include <algorithm>
#include <string>
#include <vector>

#include "tofsim/io/Exr.h"
#include "tofsim/util/Error.h"

namespace tofsim::io {

void writeDepthExr(const std::filesystem::path& path, const Image& depth_m) {
  TOFSIM_CHECK(depth_m.channels == 1);
  Image both(depth_m.width, depth_m.height, 2);
  for (std::size_t i = 0; i < depth_m.data.size(); ++i) {
    both.data[2 * i] = depth_m.data[i];
    both.data[2 * i + 1] = depth_m.data[i];
  }
  writeExr(path, both, {"Y", "Z"});
}

Image readDepthExr(const std::filesystem::path& path) {
  std::vector<std::string> names;
  const Image image = readExr(path, &names);
  // Z first: it is the depth by name; Y alone is a depth written for readers.
  for (const char* wanted : {"Z", "Y"}) {
    const auto it = std::find(names.begin(), names.end(), wanted);
    if (it == names.end()) continue;
    const auto c = static_cast<int32_t>(it - names.begin());
    Image depth(image.width, image.height, 1);
    for (std::size_t i = 0; i < depth.data.size(); ++i) {
      depth.data[i] = image.data[i * image.channels + c];
    }
    return depth;
  }
  throw InputError(FileLoc{path.string()}, "", "depth EXR has neither channel Z nor Y");
}

}  // namespace tofsim::io
