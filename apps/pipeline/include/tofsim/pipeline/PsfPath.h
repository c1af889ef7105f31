#pragma once
// Where a render applies the lens's PSF (camera.psf). On every time bin of
// the transient (PsfSegments.h) it is exact for every output and sensor but
// holds the whole volume and convolves T x 3 planes per component. A CW-ToF
// camera's raws are linear in each bin's light with weights common to all
// pixels, so the same PSF on its F x N noise-free raw images gives the same
// charges (to rounding) for a fraction of the cost: when nothing the run
// writes needs the blurred transient itself, the render skips PsfSegments,
// each CW-ToF sensor convolves its signal charges (StreamOptions::psfOnRaws)
// and the steady image is convolved once.

#include "tofsim/config/RunConfig.h"

namespace tofsim::pipeline {

enum class PsfPath {
  None,       ///< no camera.psf
  Transient,  ///< PsfSegments on every bin, before every consumer
  Raws,       ///< on the CW-ToF sensors' raws and on the steady image
};

/// Raws when `config` has camera.psf and the run writes nothing made of the
/// blurred transient but the steady image and CW-ToF sensors: no volume
/// file (output.transient, direct, indirect, bounces), no frames or video,
/// only CW-ToF sensors, none with a fixed-pattern delay (delay_sigma,
/// delay_map: the delay acts in each pixel's correlation, so blurring its
/// charges would give scattered light the wrong pixel's delay) nor
/// multipath_by_order (its light by bounce order would need blurring too).
/// Transient otherwise, and always when `forceTransient` (the tests compare
/// the two paths).
PsfPath choosePsfPath(const config::RunConfig& config, bool forceTransient = false);

}  // namespace tofsim::pipeline
