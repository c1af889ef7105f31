#pragma once
// Private to the config module: the `light:` section's parameter table (see RunFields.h).

#include <array>
#include <tuple>

#include "RunFields.h"
#include "tofsim/capture/Light.h"

namespace tofsim::config {

// clang-format off
inline constexpr std::array<Name<capture::Light::Type>, 2> kLightTypeNames{
    {{"point", capture::Light::Type::Point}, {"spot", capture::Light::Type::Spot}}};

// The keys of `light`. `direction` is normalised and `cone_falloff` checked
// against `cone_angle` by the section's parser (RunSections.cpp).
inline constexpr auto kLightFields = std::tuple{
    In{"type", &LightConfig::light, &capture::Light::type, Choice<capture::Light::Type>{kLightTypeNames},
       {.doc = "`point` or `spot`"}},
    Field{"attach_to_camera", &LightConfig::attach_to_camera, Flag{},
          {.doc = "put the light at the camera (plus `offset`) aimed along the view, as ToF illuminators are mounted; then `position`/`direction` are ignored"}},
    Field{"offset", &LightConfig::offset_camera_m, Vec3{},
          {.unit = "m", .doc = "with `attach_to_camera`: right, up, forward of the pinhole"}},
    In{"position", &LightConfig::light, &capture::Light::position_world, Vec3{},
       {.unit = "m", .doc = "light position"}},
    In{"direction", &LightConfig::light, &capture::Light::direction_world, Vec3{},
       {.doc = "spot axis (normalised; not zero)"}},
    In{"cone_angle", &LightConfig::light, &capture::Light::cone_half_angle_deg, Angle{{.min = 0.0, .max = 180.0, .minExclusive = true}},
       {.doc = "spot half angle"}},
    In{"cone_falloff", &LightConfig::light, &capture::Light::cone_falloff_deg, Angle{.rangeDoc = "in [0, cone_angle]"},
       {.doc = "spot edge softening"}},
    In{"intensity", &LightConfig::light, &capture::Light::intensity_W_per_sr, Rgb{},
       {.unit = "W/sr", .doc = "radiant intensity per channel (R, G, B)"}},
};
// clang-format on

}  // namespace tofsim::config
