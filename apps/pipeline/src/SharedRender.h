#pragma once
// Private to the pipeline: a batch run that takes its render from another
// run of the same render key (RunContentKey.h), runs that differ only in
// their sensors. The run's folder gets a copy of the other run's render
// files (every file its manifest lists but sensors/ and the effective
// config), its own sensors sensed from the copied volume as `tofsim sense`
// senses a saved render (SenseRun.h: the same bytes as the sensors of a
// render of its own), and its own record; its manifest names the run whose
// render it took. Copies, not links: each run folder stands alone, so a
// resumed batch skips or redoes each run by its own manifest.

#include <filesystem>
#include <string>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/RenderRun.h"

namespace tofsim::pipeline {

class PreparedRenderer;

/// "" when a run of `config` can take its render from a saved run of the same
/// render key: its sensors see exactly what that render saved (the total
/// volume as transient.npy, the direct light and depth when written). Else
/// why not: an NLOS scan, a sequence or a `rays:` imager, output.format hdf5 (the sensors'
/// arrays go into capture.h5), no output.transient, camera.psf (the
/// sensors may take the light before it), a cwtof sensor with
/// multipath_by_order (light by bounce order).
std::string sharedRenderObstacle(const config::RunConfig& config);

/// The run of `config` into options.outputDirectory from the render saved in
/// `source` (a finished batch run of the same render key, whose name is
/// options.batchManifest->renderFrom), staged and committed as a render's
/// set. Throws InputError when the source's manifest records another render
/// key or a copied file differs from what it lists.
RunSummary senseFromSavedRender(const config::RunConfig& config,
                                const std::filesystem::path& source,
                                PreparedRenderer& prepared, const RunOptions& options);

}  // namespace tofsim::pipeline
