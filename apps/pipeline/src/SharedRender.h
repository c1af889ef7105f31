#pragma once
// Private to the pipeline: a batch run that takes its render from another
// run of the same render key (RunContentKey.h), runs that differ only in
// their sensors. The run's folder gets a copy of the other run's render
// files (every file its manifest lists but sensors/ and the effective
// config), its own sensors sensed from the copied volume (or from the one
// the batch saved for it: SharedVolumes) as `tofsim sense` senses a saved
// render (SenseRun.h: the same bytes as the sensors of a render of its
// own), and its own record; its manifest names the run whose
// render it took. Copies, not links: each run folder stands alone, so a
// resumed batch skips or redoes each run by its own manifest.

#include <cstddef>
#include <deque>
#include <filesystem>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/pipeline/RunContentKey.h"

namespace tofsim::pipeline {

class PreparedRenderer;

/// "" when a run of `config` can take its render from another run of the
/// same render key: its sensors see exactly what that render gives them (the
/// total volume, the direct light and depth when written). Else why not: an
/// NLOS scan, a sequence, a lidar or a `rays:` imager, output.format hdf5
/// (the sensors' arrays go into capture.h5), a camera.psf on every time bin
/// (PsfPath.h: the sensors' cwtof_psf_error takes the light before it), a
/// cwtof sensor with multipath_by_order (light by bounce order).
std::string sharedRenderObstacle(const config::RunConfig& config);

/// Whether such a run saves no transient.npy (output.transient: false, as
/// for a camera.psf on the CW-ToF raws): the render's volume is then shared
/// through the batch's SharedVolumes, as the light before the PSF, which the
/// sensors apply to their raws as the render's did.
bool sharesThroughTheBatch(const config::RunConfig& config);

/// The run of `config` into options.outputDirectory from the render saved in
/// `source` (a finished batch run of the same render key, whose name is
/// options.batchManifest->renderFrom), staged and committed as a render's
/// set; the volume read from options.sharedVolume when given (the source
/// saved none of its own). Throws InputError when the source's manifest
/// records another render key or a copied file differs from what it lists.
RunSummary senseFromSavedRender(const config::RunConfig& config,
                                const std::filesystem::path& source,
                                PreparedRenderer& prepared, const RunOptions& options);

/// The volumes a batch saves for the runs that share a render through it
/// (sharesThroughTheBatch): <output>/.shared-volumes-<pid>/<render key>/
/// with transient.npy and transient.json, hidden (not a run), written by the
/// run that renders the key and read by the runs that take its render. Only
/// for keys with two or more such runs pending. Removed with what it holds
/// when the batch ends (interrupted too), so a resumed batch renders such a
/// key once again: a run done before is no source for it (its volume is
/// gone; SharedRenders). The folders of batches killed before their end are
/// removed by the next batch over the output.
class SharedVolumes {
 public:
  SharedVolumes(const std::filesystem::path& outputRoot, const std::vector<RunContentKey>& keys,
                const std::vector<bool>& throughTheBatch, const std::deque<std::size_t>& pending);
  ~SharedVolumes();
  SharedVolumes(const SharedVolumes&) = delete;
  SharedVolumes& operator=(const SharedVolumes&) = delete;

  /// Where run `run` saves (rendering) or reads (taking the render) its key's
  /// volume: RunOptions::sharedVolume; empty for a run that shares none.
  const std::filesystem::path& folder(std::size_t run) const { return folders_.at(run); }

 private:
  std::filesystem::path root_;
  std::vector<std::filesystem::path> folders_;
};

}  // namespace tofsim::pipeline
