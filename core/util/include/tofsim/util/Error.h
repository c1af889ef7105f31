#pragma once
// Two error channels (see STYLE.md):
//  - InputError: bad input or environment (a config key, a missing file, no GL
//    context). Thrown with a location, caught in main, mapped to a non-zero exit.
//  - TOFSIM_CHECK: a programmer bug. Always on; prints the condition and
//    aborts. TOFSIM_CHECK_EQ / _NE / _LT / _LE / _GT / _GE (as pbrt-v4's
//    CHECK_EQ) also print both operands' values.

#include <sstream>
#include <stdexcept>
#include <string>

namespace tofsim {

/// Where in an input file something was found. line and column are 1-based;
/// 0 means unknown.
struct FileLoc {
  std::string file;
  int line = 0;
  int column = 0;

  /// "file:line:col", "file:line", "file" or "" depending on what is known.
  std::string toString() const;
};

/// Bad input or environment. what() is one line: "loc: key: message".
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message);
  InputError(const FileLoc& loc, const std::string& key, const std::string& message);

  const FileLoc& location() const { return loc_; }
  const std::string& key() const { return key_; }

 private:
  FileLoc loc_;
  std::string key_;
};

[[noreturn]] void checkFailed(const char* expr, const char* file, int line,
                              const std::string& detail);

namespace detail {
/// "a vs b" with both values as an ostream prints them.
template <class A, class B>
std::string checkOperands(const A& a, const B& b) {
  std::ostringstream out;
  out << a << " vs " << b;
  return out.str();
}
}  // namespace detail

}  // namespace tofsim

// Evaluates each operand once; on failure prints "a OP b" and both values.
#define TOFSIM_CHECK_OP(a, op, b)                                                           \
  do {                                                                                      \
    const auto& tofsimCheckA_ = (a);                                                        \
    const auto& tofsimCheckB_ = (b);                                                        \
    if (!(tofsimCheckA_ op tofsimCheckB_)) {                                                \
      ::tofsim::checkFailed(#a " " #op " " #b, __FILE__, __LINE__,                          \
                            ::tofsim::detail::checkOperands(tofsimCheckA_, tofsimCheckB_)); \
    }                                                                                       \
  } while (0)
#define TOFSIM_CHECK_EQ(a, b) TOFSIM_CHECK_OP(a, ==, b)
#define TOFSIM_CHECK_NE(a, b) TOFSIM_CHECK_OP(a, !=, b)
#define TOFSIM_CHECK_LT(a, b) TOFSIM_CHECK_OP(a, <, b)
#define TOFSIM_CHECK_LE(a, b) TOFSIM_CHECK_OP(a, <=, b)
#define TOFSIM_CHECK_GT(a, b) TOFSIM_CHECK_OP(a, >, b)
#define TOFSIM_CHECK_GE(a, b) TOFSIM_CHECK_OP(a, >=, b)

#define TOFSIM_CHECK(cond)                                             \
  do {                                                                 \
    if (!(cond)) ::tofsim::checkFailed(#cond, __FILE__, __LINE__, {}); \
  } while (0)

#define TOFSIM_CHECK_MSG(cond, msg)                                       \
  do {                                                                    \
    if (!(cond)) ::tofsim::checkFailed(#cond, __FILE__, __LINE__, (msg)); \
  } while (0)
