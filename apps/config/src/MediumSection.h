#pragma once
// Private to the config module: issue 42's `medium:` section, the
// homogeneous participating medium that fills the scene (fog, smoke, turbid
// water), read into RunConfig::render.medium with located errors:
//   medium: {sigma_a: 0.01, sigma_s: [0.04, 0.05, 0.06],
//            phase: {model: henyey_greenstein, g: 0.6}, index_of_refraction: 1.33}
//   medium: {visibility: 50 m}   (fog: Koschmieder, albedo and g of fog droplets)
// Per-region media, each inside a closed glTF mesh, into RunConfig::
// render.media (and RunConfig::media, their locations):
//   media: [{region: water_tank, sigma_a: [0.3, 0.05, 0.02], sigma_s: 0.1,
//            index_of_refraction: 1.33}]
// (the meshes are resolved and checked once the scene is read:
// pipeline::configureScene).

#include <yaml-cpp/yaml.h>

#include "ConfigNode.h"
#include "tofsim/config/RunConfig.h"

namespace tofsim::config {

/// Koschmieder's law: sigma_t = ln(1 / 0.02) / V, the extinction at which a
/// black target at the meteorological visibility V keeps a 2 % contrast.
inline constexpr double kKoschmieder = 3.912;
/// Fog's defaults with `visibility` (shared/research/media-delays-lidar.md
/// §2.2, [MIE]: Mie theory, miepython 3.3.0, on the Podzimek 1997 fog
/// droplet distribution, lognormal r_g = 4.69 um, sigma_g = 1.504; at
/// 905 nm, the lidars' wavelength): single-scattering albedo 0.99996,
/// Henyey-Greenstein g = 0.845. HG with that g has p(pi) = 0.0035 / sr, about
/// 15x less backscatter than the Mie phase function's 0.052 / sr (the same
/// note): a fog lidar's backscatter peak is low by that factor.
inline constexpr float kFogAlbedo = 0.99996f;
inline constexpr float kFogG = 0.845f;

/// The root's `medium:` into config.render.medium and config.medium (the
/// view and the time axis read before it; its index of refraction sets
/// time.index_of_refraction), and `media:` into config.render.media.
void parseMedium(const ConfigNode& root, RunConfig& config);

/// The effective config's `medium:` (config.medium set), in the form it was
/// written: `visibility` and `albedo`, or `sigma_a` and `sigma_s`.
YAML::Node mediumNode(const RunConfig& config);

/// The effective config's `media:` (config.render.media not empty), each
/// entry with sigma_a and sigma_s (a `visibility` written as its values).
YAML::Node mediaNode(const RunConfig& config);

}  // namespace tofsim::config
