#pragma once
// NumPy arrays that own their memory: the vector is moved into a capsule that
// the array holds as its base, so an array outlives the result it came from
// without a copy.

#include <pybind11/numpy.h>

#include <vector>

#include "tofsim/volume/TransientVolume.h"

namespace tofsim::python {

/// What the bindings accept as input arrays: anything NumPy can turn into a
/// C-order float32 array (converted, i.e. copied, only when it is not one).
using FloatArray = pybind11::array_t<float, pybind11::array::c_style | pybind11::array::forcecast>;

/// A float32 C-order array of `shape` over `values` (moved, not copied).
pybind11::array_t<float> ownedArray(std::vector<float>&& values,
                                    const std::vector<pybind11::ssize_t>& shape);
/// (H, W, T, C).
pybind11::array_t<float> volumeArray(TransientVolume&& volume);

/// {start_s, bin_width_s, bins, start_m, bin_width_m}: tofsim.TimeAxis's fields.
pybind11::dict timeAxisDict(const TimeAxis& axis);

/// A copy of an (H, W, T, C) float32 array as a volume on `axis` (whose bins
/// must be T); channels named R, G, B for three, C0, C1, ... otherwise.
TransientVolume volumeFromArray(const FloatArray& array, const TimeAxis& axis, const char* what);

}  // namespace tofsim::python
