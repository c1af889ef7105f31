#pragma once
// Private to the config module: what the run config's parameter tables need
// beside the sensors' vocabulary (sensors/ParamField.h): kinds of values a
// sensor never takes (byte counts, angles, vectors, a time axis written in
// ps) and the entry of a key held in a member of a member (render.seed is
// RunConfig::render.seed). Parsed, emitted and documented by Field*.h.

#include <glm/glm.hpp>
#include <string>
#include <type_traits>

#include "tofsim/sensors/ParamField.h"

namespace tofsim::config {

/// A byte count ("512 MiB"), written back as "<n> B"; min and max as
/// binary-unit multiples, which the docs and the error write ("1 MiB").
struct Bytes {
  double min;
  double max;
};
/// Degrees (float): "30 deg" or a bare number of degrees. `rangeDoc`, when
/// set, is a range the section checks itself (it names another key).
struct Angle {
  sensors::Range range;
  const char* rangeDoc = nullptr;
};
/// A glm::vec3 written [x, y, z].
struct Vec3 {};
/// A glm::vec3 >= 0 per channel, written as one number (all channels) or [r, g, b].
struct Rgb {};
/// A duration (double seconds) of the time axis, written back in ps.
struct Picoseconds {
  sensors::Range range;
};

/// A value whose accepted range the section checks itself over the parsed
/// struct, with its own message (the range depends on another key, or the
/// message says why): read and written as `kind`, which states no range of
/// its own, and documented with `rangeDoc`.
template <typename K>
struct Checked {
  K kind;
  const char* rangeDoc;
};
template <typename K>
Checked(K, const char*) -> Checked<K>;
template <typename K>
inline constexpr bool kIsChecked = false;
template <typename K>
inline constexpr bool kIsChecked<Checked<K>> = true;

/// One config key of struct S held in member `member` of its member `outer`.
template <typename S, typename M, typename T, typename K>
struct In {
  const char* name;
  M S::*outer;
  T M::*member;
  K kind;
  sensors::Info info;
};
template <typename S, typename M, typename T, typename K>
In(const char*, M S::*, T M::*, K, sensors::Info) -> In<S, M, T, K>;

/// True for an entry that holds a value (a Field or an In, not a Custom).
template <typename E>
inline constexpr bool kHasValue = sensors::kIsField<E>;
template <typename S, typename M, typename T, typename K>
inline constexpr bool kHasValue<In<S, M, T, K>> = true;

/// The value an entry names in `s` (a Field's member, an In's member of a member).
template <typename E, typename S>
auto& valueIn(const E& entry, S& s) {
  if constexpr (sensors::kIsField<E>) {
    return s.*entry.member;
  } else {
    return (s.*entry.outer).*entry.member;
  }
}

}  // namespace tofsim::config
