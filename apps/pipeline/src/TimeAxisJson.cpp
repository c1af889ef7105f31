#include "TimeAxisJson.h"

namespace tofsim::pipeline {

using json = nlohmann::ordered_json;

json timeAxisJson(const TimeAxis& axis) {
  return {{"start_s", axis.start_s},
          {"bin_width_s", axis.bin_width_s},
          {"bins", axis.bins},
          {"end_s", axis.end_s()},
          {"start_m", axis.start_m()},
          {"bin_width_m", axis.bin_width_m()},
          {"depth_start_m", axis.depthOf_m(axis.start_s)},
          {"depth_bin_width_m", axis.depthOf_m(axis.bin_width_s)},
          {"index_of_refraction", axis.index_of_refraction},
          {"camera_unwarp", axis.camera_unwarp},
          {"bin_doc", "bin t covers [start_s + t * bin_width_s, start_s + (t + 1) * bin_width_s)"},
          {"length_doc",
           "*_m: optical path length c * time; depth_*: (c / index_of_refraction) * time / 2 "
           "(one leg, not / 2, with camera_unwarp), the depth of a camera with the light at it"}};
}

}  // namespace tofsim::pipeline
