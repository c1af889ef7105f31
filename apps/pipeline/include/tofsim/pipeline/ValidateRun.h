#pragma once
// `tofsim validate`: every check `render` makes before it renders, run by
// the same functions on the same scene, so that a config validate passes is
// not refused by render at once (issue 44): the outputs' size and an NLOS
// scan's memory (checkRunSizes), the scene loaded as render loads it (its
// materials' delays and response classes; a sequence's animations), then an
// NLOS scan's relay wall, sensor and laser origins (planNlosScan) or a
// camera capture's render job and time axis (prepareCapture, with notes)
// and the video encoder when a video is asked for.

#include "tofsim/config/RunConfig.h"

namespace tofsim::pipeline {

/// Throws the first InputError render would throw before rendering; prints
/// the time axis's warnings and notes on stderr (render.strict: a proven cut
/// throws).
void validateRun(const config::RunConfig& config);

}  // namespace tofsim::pipeline
