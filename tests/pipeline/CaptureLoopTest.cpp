// pipeline::renderCaptures, the one capture loop (issue 40 item 4): captures
// in order, each into its own sink, progress counted per capture; a signal
// stops it with the capture in flight unfinished and no later capture
// begun; the bytes of every capture the same on one worker and on three.
// A still plane on the CPU backend (MovingPlaneTest's scene, 8 x 8 pixels).

#include <gtest/gtest.h>

#include <csignal>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "MovingPlaneTest.h"
#include "tofsim/capture/VolumeCollector.h"
#include "tofsim/pipeline/CaptureLoop.h"
#include "tofsim/pipeline/PreparedRenderer.h"
#include "tofsim/pipeline/RenderCapture.h"
#include "tofsim/util/Interrupt.h"

namespace tofsim::pipeline {
namespace {

// What the loop did, in the order it did it: "job 0", "sink 0", "finish 0", ...
struct Log {
  std::mutex mutex;  ///< the sinks of several workers write here
  std::vector<std::string> events;
  std::vector<std::vector<float>> light;  ///< capture i's volume (direct), once finished
  std::size_t destroyedUnfinished = 0;
};

// A capture's sink that keeps its light and says when it is finished; with
// `interruptAt`, a signal arrives during its render's first segment.
class RecordingSink : public CaptureSink {
 public:
  RecordingSink(Log& log, std::size_t i, const capture::RenderJob& job, bool interrupt)
      : log_(log),
        i_(i),
        collector_(capture::imageWidth(job.imager), capture::imageHeight(job.imager),
                   job.settings.time, capture::kChannels),
        interrupt_(*this, interrupt) {}
  ~RecordingSink() override {
    const std::lock_guard<std::mutex> lock(log_.mutex);
    if (!finished_) ++log_.destroyedUnfinished;
  }
  capture::SegmentSink& segments() override { return interrupt_; }
  void finish(const capture::RenderResult&, const RendererChoice&) override {
    const std::lock_guard<std::mutex> lock(log_.mutex);
    finished_ = true;
    log_.events.push_back("finish " + std::to_string(i_));
    if (log_.light.size() <= i_) log_.light.resize(i_ + 1);
    log_.light[i_] = collector_.direct.values();
  }

 private:
  // Before the collector: raises the signal on the first segment.
  struct Interrupting : capture::SegmentSink {
    Interrupting(RecordingSink& s, bool on) : sink(s), on(on) {}
    void consume(const capture::Segment& segment) override {
      if (on) setPendingInterruptForTesting(SIGINT);
      sink.collector_.consume(segment);
    }
    RecordingSink& sink;
    bool on;
  };
  Log& log_;
  std::size_t i_;
  capture::VolumeCollector collector_;
  Interrupting interrupt_;
  bool finished_ = false;
};

class CaptureLoopTest : public test_sequence::MovingPlaneTest {
 protected:
  void SetUp() override {
    test_sequence::MovingPlaneTest::SetUp();
    writeScene(0.0);
  }
  void TearDown() override { setPendingInterruptForTesting(0); }
  config::RunConfig config(int threads) {
    return config::loadRunConfigText(configYaml("", kTime), dir_ / "c.yaml",
                                     {{"render.threads", std::to_string(threads)}});
  }
  // Captures of one prepared scene: capture i lit at intensity i + 1, so
  // that each sink's light tells whose it is.
  CaptureLoopStats run(const config::RunConfig& c, std::size_t count, int workers, Log& log,
                       std::size_t interruptAt = SIZE_MAX,
                       std::vector<std::string>* progress = nullptr) {
    PreparedRenderer prepared;
    prepared.prepare(c);
    CaptureLoopOptions options;
    options.workers = workers;
    options.unit = "planes";
    options.captureDone = [&](std::size_t done, std::size_t total, const std::string& unit) {
      if (progress) {
        progress->push_back(std::to_string(done) + "/" + std::to_string(total) + " " + unit);
      }
    };
    return renderCaptures(
        prepared, c, count,
        [&](std::size_t i) {
          if (workers == 1) log.events.push_back("job " + std::to_string(i));
          capture::RenderJob job = prepareCapture(c, prepared.scene());
          job.light.intensity_W_per_sr = glm::vec3(static_cast<float>(i + 1));
          return job;
        },
        [&](std::size_t i, const capture::RenderJob& job) {
          if (workers == 1) log.events.push_back("sink " + std::to_string(i));
          return std::make_unique<RecordingSink>(log, i, job, i == interruptAt);
        },
        options);
  }
};

TEST_F(CaptureLoopTest, CapturesRunInOrderEachIntoItsOwnSinkWithProgressPerCapture) {
  Log log;
  std::vector<std::string> progress;
  const CaptureLoopStats stats = run(config(2), 3, 1, log, SIZE_MAX, &progress);
  EXPECT_EQ(log.events, (std::vector<std::string>{"job 0", "sink 0", "finish 0", "job 1", "sink 1",
                                                  "finish 1", "job 2", "sink 2", "finish 2"}));
  EXPECT_EQ(progress, (std::vector<std::string>{"1/3 planes", "2/3 planes", "3/3 planes"}));
  EXPECT_EQ(stats.captures, 3u);
  EXPECT_EQ(stats.renderers, 1u);
  EXPECT_EQ(stats.scenePreparations, 1u) << "one scene, one renderer: prepared once";
  EXPECT_EQ(stats.backend, "cpu");
  EXPECT_EQ(log.destroyedUnfinished, 0u);
  // Each sink holds its own capture's light: intensity i + 1 (direct light
  // is linear in it), and there is light.
  ASSERT_EQ(log.light.size(), 3u);
  double sum[3] = {0, 0, 0};
  for (std::size_t i = 0; i < 3; ++i) {
    for (float v : log.light[i]) sum[i] += v;
  }
  ASSERT_GT(sum[0], 0.0);
  EXPECT_NEAR(sum[1] / sum[0], 2.0, 1e-5);
  EXPECT_NEAR(sum[2] / sum[0], 3.0, 1e-5);
}

TEST_F(CaptureLoopTest, ASignalLeavesTheCaptureInFlightUnfinishedAndBeginsNoOther) {
  Log log;
  std::vector<std::string> progress;
  EXPECT_THROW(run(config(2), 4, 1, log, 1, &progress), Interrupted);
  // Capture 0 finished; capture 1 rendered but never finished (its sink
  // destroyed unfinished: what it staged goes with it); 2 and 3 never begun.
  EXPECT_EQ(log.events,
            (std::vector<std::string>{"job 0", "sink 0", "finish 0", "job 1", "sink 1"}));
  EXPECT_EQ(log.destroyedUnfinished, 1u);
  EXPECT_EQ(progress, (std::vector<std::string>{"1/4 planes"}));
}

TEST_F(CaptureLoopTest, SameBytesOnOneWorkerAndOnThree) {
  Log one, three;
  const CaptureLoopStats a = run(config(2), 6, 1, one);
  const CaptureLoopStats b = run(config(1), 6, 3, three);
  EXPECT_EQ(a.renderers, 1u);
  EXPECT_GE(b.renderers, 1u);
  EXPECT_LE(b.renderers, 3u);
  EXPECT_EQ(b.scenePreparations, b.renderers) << "each renderer prepares the scene once";
  EXPECT_EQ(three.destroyedUnfinished, 0u);
  ASSERT_EQ(one.light.size(), 6u);
  ASSERT_EQ(three.light.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    ASSERT_EQ(one.light[i].size(), three.light[i].size());
    EXPECT_EQ(std::memcmp(one.light[i].data(), three.light[i].data(),
                          one.light[i].size() * sizeof(float)),
              0)
        << "capture " << i;
  }
}

}  // namespace
}  // namespace tofsim::pipeline
