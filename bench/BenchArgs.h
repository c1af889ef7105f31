#pragma once
// The bench programs' positional arguments (bench/README.md gives each
// program's): argv[i] as a number where given, else the default. A value
// that is not a whole number (or, for a double, a number) ends the program
// with a message, where std::atoi read "1e3" as 1 and "abc" as 0.

#include <cstdio>
#include <cstdlib>
#include <type_traits>

namespace tofsim::bench {

template <typename T>
T arg(int argc, char** argv, int i, T fallback) {
  static_assert(std::is_arithmetic_v<T>);
  if (argc <= i) return fallback;
  const char* text = argv[i];
  char* end = nullptr;
  T value{};
  if constexpr (std::is_floating_point_v<T>) {
    value = static_cast<T>(std::strtod(text, &end));
  } else {
    value = static_cast<T>(std::strtoll(text, &end, 10));
  }
  if (end == text || *end != '\0') {
    std::fprintf(stderr, "%s: argument %d is '%s', not a number (bench/README.md)\n", argv[0], i,
                 text);
    std::exit(2);
  }
  return value;
}

}  // namespace tofsim::bench
