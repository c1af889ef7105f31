// Every input that crashed a fuzz target (fuzz/) is kept in
// tests/regressions/<loader>/ and loaded here the way the fuzz target loads
// it: it must now load or be rejected with an InputError, nothing else. Run
// under the sanitizers (scripts/run-sanitized-tests.sh) this also catches the
// original undefined behaviour or memory error coming back.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/BatchInput.h"
#include "fuzz/CameraFilesInput.h"
#include "fuzz/CaptureH5Reads.h"
#include "fuzz/IrfInput.h"
#include "fuzz/RaysInput.h"
#include "fuzz/SceneInvariants.h"
#include "fuzz/SequenceInput.h"
#include "fuzz/ResponseTableInput.h"
#include "fuzz/SpadTablesInput.h"
#include "support/TempDir.h"
#include "tofsim/config/RunConfig.h"
#include "tofsim/io/Npy.h"
#include "tofsim/io/TalCapture.h"
#include "tofsim/pipeline/SavedVolume.h"
#include "tofsim/scene/GltfLoader.h"
#include "tofsim/util/Error.h"

namespace tofsim {
namespace {

namespace fs = std::filesystem;

std::string bytesOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeBytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

class FuzzRegressionTest : public test::TempDirTest {
 protected:
  // Runs `load` on every file of tests/regressions/<kind>; returns how many.
  // Callers assert at least one, so an emptied corpus cannot pass unnoticed.
  template <typename Load>
  int forEachInput(const std::string& kind, Load load) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(fs::path(TOFSIM_REGRESSIONS_DIR) / kind)) {
      if (e.path().filename().string().front() == '.') continue;  // .keep
      SCOPED_TRACE(e.path().string());
      try {
        load(bytesOf(e.path()), e.path());
      } catch (const InputError&) {  // the expected rejection
      }
      ++n;
    }
    return n;
  }
};

TEST_F(FuzzRegressionTest, Configs) {
  fs::create_directory_symlink(fs::path(TOFSIM_SOURCE_DIR) / "configs" / "scenes", dir_ / "scenes");
  const int inputs = forEachInput("config", [&](const std::string& bytes, const fs::path&) {
    writeBytes(dir_ / "input.yaml", bytes);
    config::loadRunConfig(dir_ / "input.yaml", {});
  });
  EXPECT_GT(inputs, 0);
}

// As in fuzz/fuzz_batch.cpp: a batch file beside a tiny run config; one that
// loads has its first runs and its last made and their configs loaded.
TEST_F(FuzzRegressionTest, BatchFiles) {
  fs::create_directory_symlink(fs::path(TOFSIM_SOURCE_DIR) / "configs" / "scenes", dir_ / "scenes");
  const int inputs = forEachInput("batch", [&](const std::string& bytes, const fs::path&) {
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    fuzz::runBatchInput(config::loadBatchConfig(fuzz::writeBatchInput(dir_, data, bytes.size())));
  });
  EXPECT_GT(inputs, 0);
}

// As in fuzz/fuzz_irf.cpp: a SPAD's measured response, CSV or .npy.
TEST_F(FuzzRegressionTest, IrfFiles) {
  fs::create_directory_symlink(fs::path(TOFSIM_SOURCE_DIR) / "configs" / "scenes", dir_ / "scenes");
  const int inputs = forEachInput("irf", [&](const std::string& bytes, const fs::path&) {
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    const fs::path config = fuzz::writeIrfInput(dir_, data, bytes.size());
    if (!config.empty()) config::loadRunConfig(config, {});
  });
  EXPECT_GT(inputs, 0);
}

// As in fuzz/fuzz_response_table.cpp: a material's measured scattering
// delay, CSV or .npy, then the stage's taps.
TEST_F(FuzzRegressionTest, ResponseTableFiles) {
  const int inputs = forEachInput("response_table", [&](const std::string& bytes, const fs::path&) {
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    fuzz::loadResponseTable(fuzz::writeResponseTableInput(dir_, data, bytes.size()));
  });
  EXPECT_GT(inputs, 0);
}

// As in fuzz/fuzz_rays.cpp: a ray list's file, CSV or .npy.
TEST_F(FuzzRegressionTest, RayFiles) {
  fs::create_directory_symlink(fs::path(TOFSIM_SOURCE_DIR) / "configs" / "scenes", dir_ / "scenes");
  const int inputs = forEachInput("rays", [&](const std::string& bytes, const fs::path&) {
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    const fs::path config = fuzz::writeRaysInput(dir_, data, bytes.size());
    if (!config.empty()) config::loadRunConfig(config, {});
  });
  EXPECT_GT(inputs, 0);
}

// As in fuzz/fuzz_spad_tables.cpp: a SPAD's TDC DNL (.csv, .npy) or dark
// count map (.npy); one the config accepts runs through the SPAD.
TEST_F(FuzzRegressionTest, SpadTableFiles) {
  fs::create_directory_symlink(fs::path(TOFSIM_SOURCE_DIR) / "configs" / "scenes", dir_ / "scenes");
  int loaded = 0;
  const int inputs = forEachInput("spad_tables", [&](const std::string& bytes, const fs::path&) {
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    const fs::path config = fuzz::writeSpadTablesInput(dir_, data, bytes.size());
    if (config.empty()) return;
    fuzz::runSpadTables(config::loadRunConfig(config, {}));
    ++loaded;
  });
  EXPECT_GT(inputs, 0);
  EXPECT_GT(loaded, 0);  // the edges that load reach the sensor
}

// As in fuzz/fuzz_camera_files.cpp: an OpenCV lens calibration, a CW-ToF
// correlation waveform (.csv, .npy) or a vignetting map; one the config
// accepts has its rays traced and runs through the CW-ToF sensor.
TEST_F(FuzzRegressionTest, CameraFiles) {
  fs::create_directory_symlink(fs::path(TOFSIM_SOURCE_DIR) / "configs" / "scenes", dir_ / "scenes");
  int loaded = 0;
  const int inputs = forEachInput("camera_files", [&](const std::string& bytes, const fs::path&) {
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    const fs::path config = fuzz::writeCameraFilesInput(dir_, data, bytes.size());
    if (config.empty()) return;
    fuzz::runCameraFiles(config::loadRunConfig(config, {}));
    ++loaded;
  });
  EXPECT_GT(inputs, 0);
  EXPECT_GT(loaded, 0);  // the edges that load reach the sensor
}

TEST_F(FuzzRegressionTest, GltfScenes) {
  const int inputs = forEachInput("gltf", [&](const std::string& bytes, const fs::path&) {
    const bool binary = bytes.rfind("glTF", 0) == 0;
    const fs::path file = dir_ / (binary ? "input.glb" : "input.gltf");
    writeBytes(file, bytes);
    // A scene that loads must pass what fuzz_gltf checks.
    EXPECT_TRUE(fuzz::renderable(scene::loadGltf(file)));
  });
  EXPECT_GT(inputs, 0);
}

// As in fuzz/fuzz_sequence.cpp: a capture sequence config and its animated
// glTF; one that loads must give a renderable scene at every frame time.
TEST_F(FuzzRegressionTest, SequenceInputs) {
  fs::create_directory_symlink(fs::path(TOFSIM_SOURCE_DIR) / "configs" / "scenes", dir_ / "scenes");
  const int inputs = forEachInput("sequence", [&](const std::string& bytes, const fs::path&) {
    const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
    const fs::path config = fuzz::writeSequenceInput(dir_, data, bytes.size());
    EXPECT_TRUE(fuzz::sequenceFramesRenderable(config::loadRunConfig(config, {})));
  });
  EXPECT_GT(inputs, 0);
}

TEST_F(FuzzRegressionTest, NpyFiles) {
  const int inputs = forEachInput("npy", [&](const std::string& bytes, const fs::path&) {
    writeBytes(dir_ / "input.npy", bytes);
    io::readNpy(dir_ / "input.npy");
  });
  EXPECT_GT(inputs, 0);
}

// As in fuzz/fuzz_tal_capture.cpp (y-tal's NLOS capture layout, HDF5).
TEST_F(FuzzRegressionTest, TalCaptures) {
  const int inputs = forEachInput("tal_capture", [&](const std::string& bytes, const fs::path&) {
    writeBytes(dir_ / "input.hdf5", bytes);
    io::readTalCapture(dir_ / "input.hdf5");
  });
  EXPECT_GT(inputs, 0);
}

// As in fuzz/fuzz_capture_h5.cpp: a capture.h5 (output.format: hdf5), every
// kind of read H5CaptureReader offers (fuzz/CaptureH5Reads.h).
TEST_F(FuzzRegressionTest, CaptureH5Files) {
  const int inputs = forEachInput("capture_h5", [&](const std::string& bytes, const fs::path&) {
    writeBytes(dir_ / "capture.h5", bytes);
    fuzz::readCaptureH5(dir_ / "capture.h5");
  });
  EXPECT_GT(inputs, 0);
}

// As in fuzz/fuzz_saved_volume.cpp: transient.json, a NUL byte, transient.npy.
TEST_F(FuzzRegressionTest, SavedVolumes) {
  const int inputs = forEachInput("saved_volume", [&](const std::string& bytes, const fs::path&) {
    const std::size_t nul = bytes.find('\0');
    writeBytes(dir_ / "transient.json", bytes.substr(0, nul));
    writeBytes(dir_ / "transient.npy", nul == std::string::npos ? "" : bytes.substr(nul + 1));
    pipeline::loadSavedVolume(dir_);
  });
  EXPECT_GT(inputs, 0);
}

}  // namespace
}  // namespace tofsim
