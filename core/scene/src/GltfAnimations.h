#pragma once
// The document's animations read and checked into tofsim::scene::Animation.

#include <vector>

#include "GltfDocument.h"
#include "tofsim/scene/Animation.h"

namespace tofsim::scene::detail {

/// Every animation of the file, its translation, rotation and scale channels
/// with their keyframes; weights channels and channels without a node are
/// counted, not read. Throws InputError naming the file, the animation and
/// the channel or sampler for: a missing sampler or node, a targeted node
/// with a matrix, a node property animated twice in one animation, an
/// unknown interpolation, input times that are negative, not finite or not
/// strictly increasing, an accessor of the wrong type, and an output count
/// that is not the input's (three times it for CUBICSPLINE).
std::vector<Animation> readAnimations(const GltfDocument& doc);

}  // namespace tofsim::scene::detail
