// The viewer's page in a browser: headless Chromium (Debian's `chromium`)
// loads a page of a small render, clicks a pixel (view.html#click=Y,X
// dispatches a click at that pixel's centre on the image), and the histogram
// the page plotted (the values it drew, written into <pre id="plotted">)
// equals the pixel's histogram in transient.npy; a screenshot is taken.
// scripts/install-deps.sh installs Debian's chromium; skipped, saying so,
// where none is installed. New headless mode: no display needed; /dev/shm
// not used (a container's is often 64 MB); killed after 30 s (it takes
// about 3.5 s on the shared 2-core machine).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/TempDir.h"
#include "tofsim/io/Npy.h"
#include "viewer/ViewerPage.h"

namespace tofsim::test {
namespace {

namespace fs = std::filesystem;
using ViewerChromiumTest = TempDirTest;

// $TOFSIM_CHROMIUM, else the first of Debian's and Google's names on PATH.
std::string findChromium() {
  if (const char* given = std::getenv("TOFSIM_CHROMIUM"); given && *given) return given;
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    if (runShell(std::string("command -v ") + name + " >/dev/null").exitCode == 0) {
      return name;
    }
  }
  return "";
}

// The page's <pre id="plotted"> text (the DOM escapes only &, < and >; JSON
// numbers and ASCII names have none).
nlohmann::json plotted(const std::string& dom) {
  const std::string open = "<pre id=\"plotted\">";
  const std::size_t from = dom.find(open);
  const std::size_t to = dom.find("</pre>", from);
  if (from == std::string::npos || to == std::string::npos) return nullptr;
  return nlohmann::json::parse(dom.substr(from + open.size(), to - from - open.size()), nullptr,
                               false);
}

TEST_F(ViewerChromiumTest, AClickedPixelsPlottedHistogramEqualsTheNpy) {
  const std::string chromium = findChromium();
  if (chromium.empty())
    GTEST_SKIP() << "no chromium on PATH (apt-get install chromium, or set "
                    "TOFSIM_CHROMIUM): the page is not loaded in a browser";
  const fs::path out = dir_ / "render";
  const CommandResult r = renderSmallCornell(out, "--set sensors=[]");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_EQ(runCli("view " + out.string()).exitCode, 0);
  const io::NpyArray transient = io::readNpy(out / "transient.npy");  // (10, 12, 96, 3)
  const std::size_t y = 7, x = 6, bins = 96, channels = 3;
  const auto at = [&](std::size_t py, std::size_t px, std::size_t t, std::size_t c) {
    return transient.data[((py * 12 + px) * bins + t) * channels + c];
  };
  // The check can fail: the transposed pixel's histogram is another one.
  double differs = 0.0;
  for (std::size_t t = 0; t < bins; ++t) differs += std::fabs(at(y, x, t, 0) - at(x, y, t, 0));
  ASSERT_GT(differs, 0.0);

  const fs::path screenshot = dir_ / "view.png";
  // No network: a file:// page whose scripts and data are inline.
  const CommandResult dom =
      runShell("timeout 30 " + chromium +
               " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run"
               " --disable-extensions"
               " --disable-background-networking --hide-scrollbars --window-size=1280,900"
               " --screenshot=" +
               screenshot.string() + " --dump-dom 'file://" + (out / "view.html").string() +
               "#click=" + std::to_string(y) + "," + std::to_string(x) + "' 2>/dev/null");
  ASSERT_EQ(dom.exitCode, 0) << dom.output.substr(0, 2000);
  const nlohmann::json p = plotted(dom.output);
  ASSERT_TRUE(p.is_object()) << "no plotted histogram in the page's DOM";
  EXPECT_EQ(p["pixel"], nlohmann::json({y, x}));
  ASSERT_EQ(p["values"].size(), channels);
  const double scale = pageData(fileBytes((out / "view.html").string()))["volume"]["scale"];
  for (std::size_t c = 0; c < channels; ++c) {
    ASSERT_EQ(p["values"][c].size(), bins);
    for (std::size_t t = 0; t < bins; ++t) {
      const double expected = at(y, x, t, c);
      EXPECT_NEAR(p["values"][c][t].get<double>(), expected, halfTolerance(expected, scale))
          << "channel " << c << " bin " << t;
    }
  }
  // The time axis: bin centres in ns and in metres of path (transient.json).
  const double startNs = 1.5 / 0.299792458, widthNs = 0.05;  // 1.5 m (cornell_box.yaml), 50 ps
  EXPECT_NEAR(p["time_ns"][10].get<double>(), startNs + 10.5 * widthNs, 1e-9);
  EXPECT_NEAR(p["path_m"][10].get<double>(), 1.5 + 10.5 * widthNs * 0.299792458, 1e-9);
  EXPECT_GT(fs::file_size(screenshot), 1000u);
}

}  // namespace
}  // namespace tofsim::test
