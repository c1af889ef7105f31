#pragma once
// Private to the config module: the numeric tables a SPAD names besides its
// IRF (IrfFile.h): a TDC's DNL table (`tdc_dnl`, a list, or a .npy / one-
// column .csv) and a dark count map (`dark_count_map`, a 2-D .npy). Relative
// paths resolve against the config file's folder (ConfigPath.h); every bad file is an
// InputError located at the key, naming the file (and its CSV line).

#include <filesystem>
#include <string>
#include <vector>

#include "ConfigNode.h"
#include "tofsim/sensors/Spad.h"

namespace tofsim::config {

/// `tdc_dnl` of node n: a list of numbers or a file; each value finite and >
/// -1 (a code of width LSB (1 + DNL) > 0), |sum| <= 1e-6 x count. The length
/// is checked against the TDC's bins where the window is known
/// (RunConfigLoader).
sensors::SpadDnl parseDnl(const ConfigNode& n);

/// `dark_count_map` of node n: a 2-D float32 .npy (H, W) of counts / s >= 0.
/// Its shape is checked against the image in checkImage.
sensors::SpadDarkCountMap parseDarkCountMap(const ConfigNode& n);

}  // namespace tofsim::config
