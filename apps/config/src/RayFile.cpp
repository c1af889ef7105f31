#include "RayFile.h"

#include <cmath>
#include <filesystem>
#include <vector>

#include "ConfigPath.h"
#include "CsvRows.h"
#include "FieldParse.h"
#include "RaysFields.h"
#include "TableText.h"
#include "tofsim/io/FileBytes.h"

namespace tofsim::config {

namespace {

constexpr std::size_t kColumns = 6;
// 16 Mi rays: far more pixels than an image of the GL texture limit needs,
// and a bound on what a file can make the loader allocate.
constexpr std::size_t kMaxRays = std::size_t(1) << 24;
constexpr std::size_t kMaxFileBytes = std::size_t(1) << 30;

// The whole file, opened without following a link (io::readFileNoFollow).
std::string readRayFile(const ConfigNode& n, const std::filesystem::path& path) {
  try {
    return io::readFileNoFollow(path, kMaxFileBytes);
  } catch (const InputError& e) {
    n.failKey("file", std::string(e.what()) + " (a ray file is read only as a regular file of at "
                                              "most 1 GiB, not through links)");
  }
}

struct RawRay {
  int line = 0;  ///< the CSV line, or 0 for a .npy
  float values[kColumns];
};

std::vector<RawRay> readNpyRays(const ConfigNode& n, const std::filesystem::path& path,
                                const std::string& bytes) {
  io::NpyArray a;
  try {
    a = io::parseNpy(bytes, path.string());
  } catch (const InputError& e) {
    n.failKey("file", std::string(e.what()) + " (a ray .npy is an (N, 6) float32 or float64 array)");
  }
  if (a.shape.size() != 2 || a.shape[1] != kColumns) {
    std::string shape;
    for (const std::size_t d : a.shape) shape += (shape.empty() ? "" : ", ") + std::to_string(d);
    n.failKey("file", path.string() + ": expected shape (N, 6) (origin xyz, direction xyz), got (" +
                          shape + ")");
  }
  std::vector<RawRay> rays(a.shape[0]);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    for (std::size_t k = 0; k < kColumns; ++k) rays[i].values[k] = a.data[i * kColumns + k];
  }
  return rays;
}

std::vector<RawRay> readCsvRays(const ConfigNode& n, const std::filesystem::path& path,
                                const std::string& bytes) {
  std::vector<RawRay> rays;
  for (const CsvRow& row : readCsvText(n, "file", path, bytes, kColumns, "ox, oy, oz, dx, dy, dz")) {
    RawRay ray;
    ray.line = row.line;
    for (std::size_t k = 0; k < kColumns; ++k) ray.values[k] = static_cast<float>(row.cells[k]);
    rays.push_back(ray);
  }
  return rays;
}

// The rays with unit directions; a zero or non-finite value is an error at
// its row (the CSV's line, the .npy's row index).
std::vector<capture::PrimaryRay> unitRays(const ConfigNode& n, const std::filesystem::path& path,
                                          const std::vector<RawRay>& raw) {
  std::vector<capture::PrimaryRay> rays;
  rays.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const float* v = raw[i].values;
    const auto fail = [&](const std::string& message) {
      if (raw[i].line > 0) failAt(n, "file", path, raw[i].line, message);
      n.failKey("file", path.string() + ": row " + std::to_string(i) + ": " + message);
    };
    for (std::size_t k = 0; k < kColumns; ++k) {
      if (!std::isfinite(v[k])) fail("a value is not finite in float32");
    }
    const glm::vec3 origin(v[0], v[1], v[2]), direction(v[3], v[4], v[5]);
    const float length = glm::length(direction);
    if (!(length > 0.0f) || !std::isfinite(length)) fail("the direction is zero (it needs a length)");
    rays.push_back({origin, direction / length});
  }
  return rays;
}

// rays.file: the rays with unit directions; `file` receives its absolute path.
std::vector<capture::PrimaryRay> readRays(const ConfigNode& node, std::string& file) {
  const std::filesystem::path path = existingDataFile(node, "file", "ray file");
  file = path.string();
  const std::string bytes = readRayFile(node, path);
  const std::string ext = lowerExtension(path);
  if (ext != ".npy" && ext != ".csv") {
    node.failKey("file", path.string() + ": a ray file is a .npy or a .csv");
  }
  const std::vector<RawRay> raw =
      ext == ".npy" ? readNpyRays(node, path, bytes) : readCsvRays(node, path, bytes);
  if (raw.empty()) node.failKey("file", path.string() + ": holds no rays");
  if (raw.size() > kMaxRays) {
    node.failKey("file", path.string() + ": holds " + std::to_string(raw.size()) +
                             " rays, more than " + std::to_string(kMaxRays));
  }
  return unitRays(node, path, raw);
}

}  // namespace

RaysConfig parseRays(const ConfigNode& node) {
  RaysConfig out;
  capture::RayListImager& imager = out.imager;
  parseFields(node, kRaysFields, out, [&](const std::string& key) {
    if (key == "file") {
      imager.rays = readRays(node, out.file);
    } else if (key == "resolution") {
      const auto count = static_cast<double>(imager.rays.size());
      const std::vector<double> res = node.getDoubles("resolution", 2, {count, 1.0});
      const bool whole = res[0] == std::floor(res[0]) && res[1] == std::floor(res[1]);
      if (!whole || res[0] < 1 || res[1] < 1 || res[0] * res[1] != count) {
        node.failKey("resolution",
                     "must be two integers (width, height) whose product is the file's " +
                         std::to_string(imager.rays.size()) + " rays");
      }
      imager.width = static_cast<int32_t>(res[0]);
      imager.height = static_cast<int32_t>(res[1]);
    }
  });
  return out;
}

}  // namespace tofsim::config
