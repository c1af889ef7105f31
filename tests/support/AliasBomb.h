#pragma once
// A YAML "billion laughs" flow sequence for the YAML readers' tests: nine
// levels of ten aliases each, 10^9 nodes once expanded, about 200 bytes of text.

#include <string>

namespace tofsim::test {

inline std::string aliasBomb() {
  std::string text = "[&l0 lol";
  for (int level = 1; level <= 9; ++level) {
    text += ", &l" + std::to_string(level) + " [";
    for (int k = 0; k < 10; ++k) text += (k ? ", *l" : "*l") + std::to_string(level - 1);
    text += "]";
  }
  return text + "]";
}

}  // namespace tofsim::test
