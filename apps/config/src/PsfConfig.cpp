#include "PsfConfig.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "CameraFields.h"
#include "FieldParse.h"
#include "SpadTableFile.h"

namespace tofsim::config {

namespace {

PsfConfig fromFile(const ConfigNode& psf) {
  sensors::forEachField(kPsfFields, [&](const auto& entry) {
    if (kHasValue<std::decay_t<decltype(entry)>> && psf.has(entry.name)) {
      psf.failKey(entry.name, "give a kernel file or the parametric kernel, not both");
    }
  });
  PsfConfig out;
  // Finite and >= 0, or an error naming the value's (y, x).
  const PixelMap map = readPixelMap(psf, "file", "PSF kernel", "kernel value");
  out.file = map.file;
  if (map.height % 2 == 0 || map.width % 2 == 0) {
    psf.failKey("file", map.file + ": a " + std::to_string(map.height) + " x " +
                            std::to_string(map.width) +
                            " (H x W) kernel; its sizes must be odd, its centre a pixel");
  }
  try {
    out.kernel = optics::PsfKernel::fromImage(map.values, map.height, map.width);
  } catch (const InputError& e) {
    psf.failKey("file", map.file + ": " + e.what());
  }
  return out;
}

}  // namespace

PsfConfig parsePsf(const ConfigNode& camera, int32_t width, int32_t height) {
  const ConfigNode psf = camera.child("psf");
  if (!psf.isMap()) {
    psf.fail("expected a mapping: {core_sigma, halo_weight, halo_profile, halo_radius} or {file}");
  }
  if (psf.has("file")) {
    PsfConfig out = fromFile(psf);
    out.at = camera.locationOf("psf");
    return out;
  }
  PsfConfig out;
  out.at = camera.locationOf("psf");
  parseFields(psf, kPsfFields, out);
  const optics::PsfParams& p = out.params;
  if (!(std::isfinite(p.core_sigma_px) && p.core_sigma_px >= 0.0)) {
    psf.failKey("core_sigma", "must be a finite number >= 0 pixels");
  }
  if (!(p.halo_weight >= 0.0 && p.halo_weight < 1.0)) {
    psf.failKey("halo_weight", "must be in [0, 1): the halo's share of the light");
  }
  if (!(std::isfinite(p.halo_radius_px) && p.halo_radius_px >= 0.0)) {
    psf.failKey("halo_radius", "must be a finite number > 0 pixels");
  }
  if (p.halo_weight > 0.0 && !(p.halo_radius_px > 0.0)) {
    psf.failKey(psf.has("halo_radius") ? "halo_radius" : "halo_weight",
                "a halo (halo_weight > 0) needs its halo_radius > 0 pixels");
  }
  try {
    out.kernel = optics::PsfKernel::parametric(p, std::max(width, height) - 1);
  } catch (const InputError& e) {
    psf.fail(e.what());  // checked above key by key; kept for any rule added there
  }
  return out;
}

}  // namespace tofsim::config
