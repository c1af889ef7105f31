#pragma once
// A number in three significant digits ("1.23e-05"), for the figures tests
// print beside their assertions.

#include <cstdio>
#include <string>

namespace tofsim::test {

inline std::string sci(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

}  // namespace tofsim::test
