#pragma once
// Private to the pipeline: every warning a run prints, "tofsim: warning:
// <text>" on stderr, through one function, so that a capture sequence,
// whose frames would each repeat the same warnings, says each once
// (RepeatedWarningsOnce) and counts the rest.

#include <cstddef>
#include <set>
#include <string>

namespace tofsim::pipeline {

void warn(const std::string& text);

/// While one lives, a warning already printed is not printed again; its
/// end says how many were held back.
class RepeatedWarningsOnce {
 public:
  RepeatedWarningsOnce();
  ~RepeatedWarningsOnce();
  RepeatedWarningsOnce(const RepeatedWarningsOnce&) = delete;
  RepeatedWarningsOnce& operator=(const RepeatedWarningsOnce&) = delete;
};

}  // namespace tofsim::pipeline
