#pragma once
// glTF camera nodes to SceneCamera (perspective only).

#include "GltfDocument.h"
#include "NodeTransforms.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::scene::detail {

/// A glTF camera looks down its node's -Z with +Y up. Callers pass
/// perspective cameras only.
SceneCamera convertCamera(const CameraDesc& camera, const NodeInstance& instance);

}  // namespace tofsim::scene::detail
