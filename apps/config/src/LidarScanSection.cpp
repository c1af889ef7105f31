#include "LidarScanSection.h"

#include <string>
#include <utility>

#include "tofsim/config/LidarPresets.h"

namespace tofsim::config {

namespace {

constexpr int32_t kMaxCells = 1024;  // a grid's rows or columns, as a lidar's channels

void parseGrid(const ConfigNode& n, lidar::ScanGrid& g) {
  if (const auto grid = n.optionalChild("grid")) {
    if (!grid->isMap()) grid->fail("expected {rows, columns}");
    for (const auto& [key, field] :
         {std::pair{"rows", &g.rows}, std::pair{"columns", &g.columns}}) {
      const long long v = grid->getInt(key, *field);
      if (v < 1 || v > kMaxCells) {
        grid->failKey(key, "must be in [1, " + std::to_string(kMaxCells) + "]");
      }
      *field = static_cast<int32_t>(v);
    }
  }
  if (const auto fov = n.optionalChild("field_of_view")) {
    if (!fov->isMap()) fov->fail("expected {horizontal, vertical} full angles in degrees");
    g.fov_horizontal_deg = fov->getAngle_deg("horizontal", g.fov_horizontal_deg);
    g.fov_vertical_deg = fov->getAngle_deg("vertical", g.fov_vertical_deg);
    for (const auto& [key, v] : {std::pair{"horizontal", g.fov_horizontal_deg},
                                 std::pair{"vertical", g.fov_vertical_deg}}) {
      if (!(v > 0.0 && v < 170.0)) {
        fov->failKey(key, "must be in (0, 170) degrees (a full angle through a pinhole's plane)");
      }
    }
  }
  const long long rays = n.getInt("zone_rays", g.zone_rays);
  if (rays < 1 || rays > 64) n.failKey("zone_rays", "must be in [1, 64] (rays a side of a zone)");
  g.zone_rays = static_cast<int32_t>(rays);
}

}  // namespace

// lidar.preset: its values are the defaults of the lidar's keys and of
// time.bin_width / time.bins (parseTime runs after, so explicit keys win).
void applyLidarPreset(const ConfigNode& n, LidarConfig& out, TimeAxis& time) {
  if (!n.has("preset")) return;
  const std::string name = n.getString("preset", "");
  const LidarPreset* preset = findLidarPreset(name);
  if (!preset) {
    std::string names;
    for (const LidarPreset& p : lidarPresets())
      names += std::string(names.empty() ? "" : ", ") + p.name;
    n.failKey("preset", "unknown lidar preset '" + name + "' (presets: " + names +
                            "; `tofsim presets` lists their values and sources)");
  }
  LidarDefaults d{out, time};
  preset->apply(d);
  out = d.lidar;
  out.preset = name;
  time = d.time;
}

// lidar.scan and the keys that belong to another scan than the one chosen.
void parseLidarScan(const ConfigNode& n, lidar::LidarSpec& s) {
  const std::string scan = n.getString("scan", scanPatternName(s.scan));
  bool known = false;
  for (auto p :
       {lidar::ScanPattern::Spinning, lidar::ScanPattern::Raster, lidar::ScanPattern::Zones}) {
    if (scan == scanPatternName(p)) {
      s.scan = p;
      known = true;
    }
  }
  if (!known) n.failKey("scan", "must be spinning, raster or zones (got '" + scan + "')");
  const auto refuse = [&](std::initializer_list<const char*> keys, const std::string& why) {
    for (const char* key : keys) {
      if (n.has(key)) n.failKey(key, "does not apply to `scan: " + scan + "`: " + why);
    }
  };
  if (!s.gridScan()) {
    refuse({"grid", "field_of_view", "zone_rays"}, "they lay out a raster's or zones' grid");
    refuse({"frame_rate"}, "a spinning lidar's timing is its `rotation_rate`");
    return;
  }
  refuse({"channels", "azimuth", "rotation_rate"},
         s.scan == lidar::ScanPattern::Zones
             ? "its zones are `grid` over `field_of_view`, all lit at once by its flood"
             : "its beams are `grid` over `field_of_view`, fired line by line at `frame_rate`");
  if (s.scan == lidar::ScanPattern::Zones) {
    refuse({"beam_divergence", "beam_profile", "beam_rays"},
           "a zone's receiver is its whole solid angle (`zone_rays` a side)");
    refuse({"frame_rate"}, "its flood lights every zone at once (no firing order)");
  } else {
    refuse({"zone_rays"}, "a raster beam's receiver is its divergence cone (`beam_rays`)");
  }
  parseGrid(n, s.grid);
  if (s.grid.rows < 1 || !(s.grid.fov_horizontal_deg > 0.0)) {
    n.failKey(n.has("scan") ? "scan" : "preset",
              "`scan: " + scan +
                  "` needs `grid: {rows, columns}` and `field_of_view: "
                  "{horizontal, vertical}` (degrees)");
  }
}

}  // namespace tofsim::config
