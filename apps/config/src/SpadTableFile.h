#pragma once
// Private to the config module: the numeric tables a SPAD names besides its
// IRF (IrfFile.h): a TDC's DNL table (`tdc_dnl`, a list, or a .npy / one-
// column .csv), a dark count map (`dark_count_map`, a 2-D .npy) and an
// afterpulse delay density (`afterpulse_delay_table`, a .npy (n, 2) or a
// two-column .csv). Relative
// paths resolve against the config file's folder (ConfigPath.h); every bad file is an
// InputError located at the key, naming the file (and its CSV line).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ConfigNode.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::config {

/// `tdc_dnl` of node n: a list of numbers or a file; each value finite and >
/// -1 (a code of width LSB (1 + DNL) > 0). The length is checked against the
/// TDC's bins where the window is known (SensorListChecks.cpp), then the sum.
sensors::SpadDnl parseDnl(const ConfigNode& n);

/// |sum| <= 1e-6 x count (the bins fill the TDC's range): after the length,
/// so that a table one value short is reported as such, not as a bad sum.
void checkDnlSum(const ConfigNode& n, const sensors::SpadDnl& dnl);

/// A per-pixel map read from a 2-D float32 .npy (H, W), row-major.
struct PixelMap {
  std::string file;  ///< absolute
  int32_t width = 0, height = 0;
  std::vector<double> values;
};
/// `key` of node n as a PixelMap whose values are finite (and >= 0 unless
/// `signedValues`); `what` names the map and `valueName` one value in errors
/// ("dark count map", "rate"). Its shape is the caller's to check against
/// the image.
PixelMap readPixelMap(const ConfigNode& n, const char* key, const char* what, const char* valueName,
                      bool signedValues = false);

/// `dark_count_map` of node n: a 2-D float32 .npy (H, W) of counts / s >= 0.
/// Its shape is checked against the image in checkImage.
sensors::SpadDarkCountMap parseDarkCountMap(const ConfigNode& n);

/// `afterpulse_delay_table` of node n: rows (delay in s, density), a float32
/// .npy of shape (n, 2) or a two-column .csv (comma separated; '#' comments,
/// a header line allowed); at least 2 rows, delays finite, >= 0 and
/// increasing, densities finite and >= 0 with a positive area; normalised
/// (sensors::afterpulseTable).
sensors::SpadAfterpulseTable parseAfterpulseDelayTable(const ConfigNode& n);

}  // namespace tofsim::config
