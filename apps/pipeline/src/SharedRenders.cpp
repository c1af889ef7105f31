#include "SharedRenders.h"

namespace tofsim::pipeline {

SharedRenders::SharedRenders(const std::vector<RunContentKey>& keys,
                             const std::vector<bool>& shareable,
                             const std::vector<bool>& throughTheBatch,
                             const std::vector<BatchRunResult>& runs)
    : keys_(keys), shareable_(shareable), throughTheBatch_(throughTheBatch) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (shareable_[i] && !throughTheBatch_[i] && runs[i].status == BatchRunStatus::Skipped) {
      sources_.emplace(keys_[i].render, i);
    }
  }
}

std::optional<SharedRenders::Next> SharedRenders::next(std::deque<std::size_t>& pending) {
  for (auto it = pending.begin(); it != pending.end(); ++it) {
    const std::size_t run = *it;
    Next n{run, std::nullopt, false};
    if (shareable_[run]) {
      const std::string& key = keys_[run].render;
      if (const auto s = sources_.find(key); s != sources_.end()) {
        n.source = s->second;
      } else if (rendering_.count(key)) {
        continue;  // waits for that render
      } else {
        rendering_.insert(key);
        n.renders = true;
      }
    }
    pending.erase(it);
    return n;
  }
  return std::nullopt;
}

void SharedRenders::ended(std::size_t run, bool renders, bool done) {
  if (renders) rendering_.erase(keys_[run].render);
  if (done && shareable_[run]) sources_.emplace(keys_[run].render, run);
}

}  // namespace tofsim::pipeline
