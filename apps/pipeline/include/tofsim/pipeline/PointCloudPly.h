#pragma once
// A depth image as a point cloud: binary little-endian PLY 1.0, one vertex
// per pixel with a finite depth (and a non-zero mask, if given), as Open3D, CloudCompare and PCL read it.
// Properties, all float32: x, y, z (world frame, m: camera position + depth
// along the pixel's ray), cam_x, cam_y, cam_z (camera frame, m: x right,
// y down, z forward, OpenCV's convention), intensity and confidence (the
// values named by SensorOutput::point_cloud). Written atomically.

#include <filesystem>
#include <string>

#include "tofsim/capture/Camera.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

struct PointCloudImages {
  const Image* depth_m = nullptr;     ///< depth along each pixel's ray, m; NaN: no point
  const Image* intensity = nullptr;   ///< same size; nullptr: 0
  const Image* confidence = nullptr;  ///< same size; nullptr: 1
  std::string comment;                ///< one line, written as a PLY comment
  const Image* mask = nullptr;        ///< same size; 0: no point; nullptr: every finite depth
};

/// Writes `path`; returns the number of points.
std::size_t writePointCloudPly(const std::filesystem::path& path, const PointCloudImages& images,
                               const capture::Camera& camera);

}  // namespace tofsim::pipeline
