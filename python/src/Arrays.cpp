#include "Arrays.h"

#include <algorithm>
#include <string>

#include "tofsim/capture/VolumeCollector.h"

namespace py = pybind11;

namespace tofsim::python {

py::dict timeAxisDict(const TimeAxis& axis) {
  py::dict time;
  time["start_s"] = axis.start_s;
  time["bin_width_s"] = axis.bin_width_s;
  time["bins"] = axis.bins;
  time["start_m"] = axis.start_m();
  time["bin_width_m"] = axis.bin_width_m();
  return time;
}

py::array_t<float> ownedArray(std::vector<float>&& values, const std::vector<py::ssize_t>& shape) {
  auto* owned = new std::vector<float>(std::move(values));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<float>*>(p); });
  return py::array_t<float>(shape, owned->data(), base);
}

py::array_t<float> volumeArray(TransientVolume&& volume) {
  const std::vector<py::ssize_t> shape{volume.height(), volume.width(), volume.bins(),
                                       volume.channels()};
  return ownedArray(std::move(volume.values()), shape);
}

TransientVolume volumeFromArray(const FloatArray& array, const TimeAxis& axis, const char* what) {
  if (array.ndim() != 4) {
    throw py::value_error(std::string(what) + " must have shape (H, W, T, C), got " +
                          std::to_string(array.ndim()) + " dimensions");
  }
  if (array.shape(2) != axis.bins) {
    throw py::value_error(std::string(what) + " has " + std::to_string(array.shape(2)) +
                          " time bins but the time axis has " + std::to_string(axis.bins));
  }
  TransientVolume volume(static_cast<int32_t>(array.shape(1)), static_cast<int32_t>(array.shape(0)),
                         axis, capture::defaultChannelNames(static_cast<int32_t>(array.shape(3))));
  std::copy_n(array.data(), volume.size(), volume.data());
  return volume;
}

}  // namespace tofsim::python
