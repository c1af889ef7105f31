#include "RunChecks.h"

#include <string>

#include "tofsim/capture/IrCapabilities.h"
#include "tofsim/capture/RegionScattering.h"

namespace tofsim::config {

// The RSM makes one VPL per texel of each light view: one view for spots up
// to 60 degrees (half angle), six cube faces otherwise (Vpls.cpp). Bounded so
// that a typo cannot ask for hours of work or more VPLs than a dispatch can
// index.
namespace {
constexpr long long kMaxVpls = 1LL << 22;
}  // namespace

void checkVplCount(const ConfigNode& root, const RunConfig& config) {
  const capture::Light& light = config.light.light;
  const capture::IndirectSettings& s = config.render.indirect;
  // As ir::rsmViews.
  const long long faces =
      light.type == capture::Light::Type::Lambertian                                   ? 5
      : light.type == capture::Light::Type::Spot && light.cone_half_angle_deg <= 60.0f ? 1
                                                                                       : 6;
  const long long side = s.rsm_resolution;
  // A scattering medium's VPLs from the light join the first bounce.
  const long long medium = config.render.medium.scatters() || capture::regionsScatter(config.render) ? s.medium_vpls : 0;
  const long long first = faces * side * side + medium;
  // Every later bounce traces vpls_per_bounce (0: as many as the first) VPLs.
  const long long later = (s.bounces - 1) * (s.vpls_per_bounce > 0 ? s.vpls_per_bounce : first);
  if (s.enabled && first + later > kMaxVpls) {
    const ConfigNode render = root.child("render");
    const ConfigNode indirect = render.child("indirect");
    std::string what = std::to_string(side) + "^2 x " + std::to_string(faces) +
                       " light view(s) = " + std::to_string(first - medium) + " VPLs";
    if (medium > 0) what += " + " + std::to_string(medium) + " medium VPLs";
    if (later > 0) what += " + " + std::to_string(later) + " of later bounces";
    // The key that asked for the most: a given medium_vpls over the RSM's.
    const char* key = later > 0                                              ? "bounces"
                      : medium > first - medium && indirect.has("medium_vpls") ? "medium_vpls"
                                                                               : "rsm_resolution";
    indirect.failKey(key,
                     what + ", more than the limit of " + std::to_string(kMaxVpls));
  }
}

// What only some IR backends gather (capture/IrCapabilities.h): a located
// error where render.backend names one that does not (auto picks one that
// does; the reference path tracer refuses defocus when it renders).
void checkBackendCapabilities(const ConfigNode& root, const RunConfig& config) {
  if (config.nlos || config.renderer != RendererKind::InstantRadiosity ||
      config.backend != IrBackendKind::Gl) {
    return;
  }
  const capture::IrCapabilities need = capture::irNeeds(&config.camera.camera, config.render);
  const capture::IrCapabilities& gl = capture::kGlCapabilities;
  if (need.defocus && !gl.defocus) {
    root.child("camera").failKey(
        "aperture",
        "defocus runs on render.backend: cpu (or auto); the gl backend does not gather "
        "aperture samples");
  }
  if (need.merged_pixel_samples && !gl.merged_pixel_samples) {
    root.child("render")
        .child("indirect")
        .failKey(
            "merge_pixel_samples",
            "runs on render.backend: cpu (or auto); the gl backend gathers every pixel sample");
  }
  if (need.sampled_gather && !gl.sampled_gather) {
    root.child("render").child("indirect").failKey(
        "gather_pairs",
        "runs on render.backend: cpu (or auto); the gl backend gathers every (pixel, VPL) pair "
        "(set 0)");
  }
}

// sequence.mp4 is made of the frames' steady.exr: without them there is no
// video, which is said rather than skipped. Its default follows
// output.steady (so the effective config, which writes both, reloads).
void checkSequenceVideo(const ConfigNode& sequence, RunConfig& config) {
  if (config.output.steady) return;
  if (sequence.has("video") && config.sequence->video) {
    sequence.failKey("video",
                     "sequence.mp4 is made of the frames' steady images: it needs "
                     "output.steady: true (or set sequence.video: false)");
  }
  config.sequence->video = false;
}

// What an nlos capture cannot do: the outputs of a camera image.
void checkNlosRun(const ConfigNode& root) {
  if (const auto output = root.optionalChild("output")) {
    for (const char* key :
         {"steady", "depth", "frames", "video", "frame_pngs", "components", "video_tone_map",
          "video_stride", "video_window", "video_fps", "plot_ranges"}) {
      if (output->has(key)) {
        output->failKey(key,
                        "does not apply to an nlos capture (it writes H.npy, its grids and "
                        "capture.hdf5: configs/README.md, `nlos`)");
      }
    }
  }
}

}  // namespace tofsim::config
