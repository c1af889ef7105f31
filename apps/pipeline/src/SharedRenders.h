#pragma once
// Private to the batch: which pending run starts next, and whether it renders
// or takes the render of a finished run of its render key (SharedRender.h).
// A run that can share (`shareable`) takes the render of a finished run of
// its render key (done before, or in this batch); while another run of its
// key is rendering, it waits for it; else it renders, and the runs of its key
// wait for it. A run that cannot share renders as before. When the render a
// run waits for fails, the next run of the key renders instead. A run that
// shares through the batch's saved volume (`throughTheBatch`, SharedRender.h)
// takes only a render of this batch: a run done before left no volume.

#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "tofsim/pipeline/BatchRun.h"
#include "tofsim/pipeline/RunContentKey.h"

namespace tofsim::pipeline {

class SharedRenders {
 public:
  /// The runs skipped as done (finished before) are sources from the start,
  /// but those that share through the batch.
  SharedRenders(const std::vector<RunContentKey>& keys, const std::vector<bool>& shareable,
                const std::vector<bool>& throughTheBatch, const std::vector<BatchRunResult>& runs);

  struct Next {
    std::size_t run = 0;
    std::optional<std::size_t> source;  ///< the run whose render it takes
    bool renders = false;               ///< it renders its key for others
  };
  /// The first run of `pending` that need not wait, taken out of it; none
  /// when every pending run waits for a render.
  std::optional<Next> next(std::deque<std::size_t>& pending);
  /// Run `run` ended (or was not started: `done` false); `renders` as next()
  /// said. A done shareable run is a source for its key from now on.
  void ended(std::size_t run, bool renders, bool done);
  /// Run `run` was found done by another batch instead of started.
  void doneElsewhere(std::size_t run, bool renders) {
    ended(run, renders, !throughTheBatch_[run]);
  }
  /// No run is going: nothing is being rendered for anyone.
  void noneRendering() { rendering_.clear(); }

 private:
  std::vector<RunContentKey> keys_;  // copies: callers may pass temporaries
  std::vector<bool> shareable_;
  std::vector<bool> throughTheBatch_;
  std::map<std::string, std::size_t> sources_;  ///< render key -> a finished run
  std::set<std::string> rendering_;             ///< render keys being rendered
};

}  // namespace tofsim::pipeline
