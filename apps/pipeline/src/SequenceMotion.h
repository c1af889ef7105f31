#pragma once
// Private to the pipeline: a capture sequence's motion ground truth for one
// frame (SequenceRun.cpp). Each pixel centre's first surface at the frame's
// time is found (its triangle and barycentric point) and found again in the
// scene at the next frame's time: the scene flow is that point's 3D
// displacement, the optical flow its displacement on the image, from where
// the frame's camera sees it to where the next frame's camera does (ego
// motion included). Where the pixel sees no surface both are NaN.

#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/capture/Imager.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/scene/AnimatedScene.h"
#include "tofsim/volume/TransientVolume.h"

namespace tofsim::pipeline {

struct MotionFields {
  Image sceneFlow_m;     ///< (H, W, 3): world-space displacement (x, y, z), m
  Image opticalFlow_px;  ///< (H, W, 2): image displacement (dx right, dy down), pixels
};

/// The motion of the surfaces `config`'s camera sees from t0_s to t1_s.
/// `scene` is moved in place (left at t1_s).
MotionFields motionFields(const config::RunConfig& config, const scene::AnimatedScene& animated,
                          scene::Scene& scene, double t0_s, double t1_s);

/// scene_flow.npy and optical_flow.npy in `dir`; their names appended to `files`.
void writeMotionFields(const std::filesystem::path& dir, const MotionFields& motion,
                       std::vector<std::string>& files);

}  // namespace tofsim::pipeline
