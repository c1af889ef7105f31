#pragma once
// A batch's results table: <output>/results.csv and results.json (a shard's:
// results-K-of-N.csv/.json), one row per run of the batch (of the shard),
// written atomically when the batch ends (after an interrupt too; not by a
// dry run) and rewritten by every batch over the same output, so a resumed
// batch's table has the runs it skipped with their numbers too.
//
// A row: the run's name, its swept values (one column per varied key), its
// folder, its status and seconds (BatchRunResult), the run whose render it
// used (its manifest's `render.from`: itself, or a run of the same render
// key, configs/README.md "Sensor-only runs share their render"), and for a
// run that is done or skipped each sensor image's summary from its files
// (sensors/<sensor>/<output>.json of kind `image` and its .npy): `mean` of
// the finite values, `valid_fraction` (finite values over all), and for
// signed outputs (errors) `mean_abs`. A value with no finite pixel is empty
// (CSV) or null (JSON).

#include <filesystem>
#include <string>

#include "tofsim/config/BatchConfig.h"
#include "tofsim/pipeline/BatchRun.h"

namespace tofsim::pipeline {

/// "results" or "results-K-of-N": the table's file name without extension.
std::string batchResultsStem(const BatchOptions& options);

/// Writes <output>/<stem>.csv and .json for `summary`'s runs; returns the
/// CSV's path.
std::filesystem::path writeBatchResults(const config::BatchConfig& batch,
                                        const BatchOptions& options,
                                        const BatchSummary& summary);

}  // namespace tofsim::pipeline
