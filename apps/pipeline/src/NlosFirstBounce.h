#pragma once
// The laser spot's own return (an NLOS capture's first bounce): the light
// the spot sends straight back to a sensor point whose cell on the wall holds
// it -- every point of a confocal scan, at the start of its histogram. It is
// not in H (y-tal's convention); the sensors see it, so that a gated SPAD
// can keep it out.

#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/NlosScan.h"
#include "tofsim/volume/TimeAxis.h"

namespace tofsim::pipeline {

/// In H's layout (time slowest): the spot's radiance averaged over the sensor
/// point's grid cell, albedo(l) x power / (pi x cell area) summed over R, G,
/// B, in the bin of the spot's optical path (0, or the two legs with
/// account_first_and_last_bounces); nothing where l is outside the cell or
/// the path off the axis. A relay wall with a scattering delay spreads it
/// from that bin on by the wall's kernel (the stage's bin integrals: the wall
/// is the spot's one delayed vertex).
std::vector<float> nlosFirstBounce(const config::RunConfig& config, const NlosScanGeometry& scan,
                                   const scene::Scene& scene, const TimeAxis& axis);

}  // namespace tofsim::pipeline
