// tofsim: the command-line interface. Parses arguments, calls one library
// function per subcommand and maps errors to exit codes:
//   0 success, 1 bad input or environment (one line on stderr), 2 usage,
//   130 / 143 interrupted by SIGINT / SIGTERM (earlier results kept unchanged).

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "tofsim/config/RunConfig.h"
#include "tofsim/pipeline/AxisReport.h"
#include "tofsim/pipeline/BatchRun.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/CompareRun.h"
#include "tofsim/pipeline/ExitCode.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/pipeline/RunContentKey.h"
#include "tofsim/pipeline/SceneInfo.h"
#include "tofsim/pipeline/SenseRun.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"

namespace {

using namespace tofsim;

std::vector<config::Override> parseOverrides(const std::vector<std::string>& sets) {
  std::vector<config::Override> overrides;
  for (const std::string& s : sets) overrides.push_back(config::parseOverride(s));
  return overrides;
}

// --strict is a documented shorthand for --set render.strict=true.
std::vector<config::Override> parseOverrides(const std::vector<std::string>& sets, bool strict) {
  std::vector<config::Override> overrides = parseOverrides(sets);
  if (strict) overrides.push_back({"render.strict", "true"});
  return overrides;
}

int runRenderCommand(const std::string& configPath, const std::string& outputDir,
                     const std::vector<std::string>& sets, bool quiet, bool strict,
                     const std::string& platform, const std::string& renderer,
                     const std::string& backend, const std::string& batchRun) {
  std::vector<config::Override> overrides = parseOverrides(sets, strict);
  // --renderer is a documented shorthand for --set render.renderer=...
  if (!renderer.empty()) overrides.push_back({"render.renderer", renderer});
  // --backend likewise for --set render.backend=...
  if (!backend.empty()) overrides.push_back({"render.backend", backend});
  const config::RunConfig config = config::loadRunConfig(configPath, overrides);
  pipeline::RunOptions options;
  options.outputDirectory = outputDir;
  options.quiet = quiet;
  options.eglPlatform =
      platform.empty() ? gl::eglPlatformFromEnvironment() : gl::parseEglPlatform(platform);
  // A batch run: the key is computed here, from the config this render
  // loaded, so the manifest records what was rendered.
  if (!batchRun.empty()) options.batchManifest = {batchRun, pipeline::runContentKey(config)};
  const pipeline::RunSummary summary = pipeline::runRender(config, options);
  if (!quiet) std::fputs(pipeline::renderSummaryText(config, summary).c_str(), stderr);
  return 0;
}

int runSenseCommand(const std::string& configPath, const std::string& volumeDir,
                    const std::string& outputDir, const std::vector<std::string>& sets,
                    bool quiet) {
  const config::RunConfig config = config::loadRunConfig(configPath, parseOverrides(sets));
  pipeline::SenseOptions options;
  options.volumeDirectory = volumeDir;
  options.outputDirectory = outputDir;
  options.quiet = quiet;
  const pipeline::SenseSummary summary = pipeline::runSense(config, options);
  if (!quiet) {
    std::fprintf(stderr, "sense: %.2f s; wrote %zu file(s) to %s\n", summary.seconds,
                 summary.files.size(), (summary.outputDirectory / "sensors").string().c_str());
  }
  return 0;
}

int runCompareCommand(const std::string& a, const std::string& b, const std::string& outputDir) {
  const std::filesystem::path out =
      outputDir.empty() ? std::filesystem::path(a) : std::filesystem::path(outputDir);
  const pipeline::CompareSummary summary = pipeline::runCompare(a, b, out);
  std::printf("A (under test): %s\nB (reference):  %s\n%s%s\n", a.c_str(), b.c_str(),
              compare::summaryTable(summary.comparison).c_str(),
              pipeline::componentsTable(summary.components).c_str());
  std::fprintf(stderr, "compare: wrote %zu file(s) to %s\n", summary.files.size(),
               out.string().c_str());
  return 0;
}

int runValidateCommand(const std::string& configPath, const std::vector<std::string>& sets,
                       bool strict) {
  const config::RunConfig config = config::loadRunConfig(configPath, parseOverrides(sets, strict));
  pipeline::checkRunSizes(config);     // output.max_bytes, an NLOS scan's memory
  pipeline::validateTimeAxis(config);  // warnings and notes on stderr; --strict: a proven cut fails
  std::printf("%s: ok\n", configPath.c_str());
  return 0;
}

int runBatchCommand(const std::string& batchPath, const std::vector<std::string>& sets, int jobs,
                    const std::string& shard, bool dryRun, bool verify, bool quiet) {
  pipeline::BatchOptions options;
  options.batchFile = batchPath;
  options.overrides = parseOverrides(sets);
  options.jobs = jobs;
  if (!shard.empty()) pipeline::parseShard(shard, options.shardIndex, options.shardCount);
  options.dryRun = dryRun;
  options.verify = verify;
  options.quiet = quiet;
  const pipeline::BatchSummary summary = pipeline::runBatch(options);
  // The table also after an interrupt: it says which runs are left.
  std::fputs(pipeline::formatBatchSummary(summary, dryRun).c_str(), stdout);
  std::fflush(stdout);
  return summary.exitCode();
}

int runInfoCommand(const std::string& scenePath) {
  std::fputs(pipeline::describeScene(scenePath).c_str(), stdout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tofsim: time-of-flight sensor simulator (transient instant radiosity)"};
  app.set_version_flag("--version", std::string("tofsim ") + tofsim::pipeline::kVersion);
  app.require_subcommand(1);

  std::string configPath, outputDir, platform, volumeDir, renderer, backend, dirA, dirB;
  // -o "" would silently mean "no -o" (the config's output.directory, or A):
  // an empty folder name is a usage error naming the option.
  const CLI::Validator notEmpty(
      [](const std::string& s) { return s.empty() ? "must not be empty" : std::string(); }, "",
      "NOT_EMPTY");
  std::vector<std::string> sets;
  bool quiet = false, strict = false;
  const char* strictHelp =
      "Light cut off by the time axis or a sensor window is an error (= --set render.strict=true)";

  CLI::App* render = app.add_subcommand("render", "Render a config's transient volume and outputs");
  render->add_option("config", configPath, "YAML config file")->required();
  render->add_option("-o,--output", outputDir, "Output directory (default: output.directory)")
      ->check(notEmpty);
  render->add_option("--set", sets, "Override a config key: key.path=value (repeatable)");
  render->add_flag("-q,--quiet", quiet, "No progress output");
  render->add_flag("--strict", strict, strictHelp);
  render->add_option("--egl-platform", platform,
                     "auto | surfaceless | device (default: $TOFSIM_EGL_PLATFORM or auto)");
  render->add_option("--renderer", renderer, "ir | reference (same as --set render.renderer=...)")
      ->check(CLI::IsMember({"ir", "reference"}));
  render->add_option("--backend", backend, "auto | gl | cpu (same as --set render.backend=...)")
      ->check(CLI::IsMember({"auto", "gl", "cpu"}));
  // Internal, for `tofsim batch`: write the run's manifest.json last.
  std::string batchRun;
  render->add_option("--batch-run", batchRun, "Batch run name (internal)")->group("");

  CLI::App* sense = app.add_subcommand(
      "sense", "Run a config's sensors on a saved render (uses only sensors: and render.seed)");
  sense->add_option("config", configPath, "YAML config file")->required();
  sense->add_option("--volume", volumeDir, "Folder of a render: transient.npy + transient.json")
      ->required();
  sense->add_option("-o,--output", outputDir, "Output directory (default: the --volume folder)")
      ->check(notEmpty);
  sense->add_option("--set", sets, "Override a config key: key.path=value (repeatable)");
  sense->add_flag("-q,--quiet", quiet, "No progress output");

  CLI::App* compareCommand = app.add_subcommand(
      "compare", "Error metrics of render A against reference B (two output directories)");
  compareCommand->add_option("a", dirA, "Output directory under test")->required();
  compareCommand->add_option("b", dirB, "Output directory of the reference")->required();
  compareCommand
      ->add_option("-o,--output", outputDir, "Where to write the comparison files (default: A)")
      ->check(notEmpty);

  CLI::App* validate = app.add_subcommand("validate", "Check a config without rendering");
  validate->add_option("config", configPath, "YAML config file")->required();
  validate->add_option("--set", sets, "Override a config key: key.path=value (repeatable)");
  validate->add_flag("--strict", strict, strictHelp);

  CLI::App* batch = app.add_subcommand(
      "batch", "Run a batch file's runs and sweeps, each into <output>/<run name>/ (resumable)");
  std::string shard;
  int jobs = 1;
  bool dryRun = false, verify = false;
  batch->add_option("batch", configPath, "Batch YAML file (configs/README.md, Batch files)")
      ->required();
  batch->add_option("--set", sets, "Override a config key in every run: key.path=value");
  batch->add_option("-j,--jobs", jobs, "Runs at once, each on a worker process that keeps its renderer (default 1)")
      ->check(CLI::Range(1, tofsim::pipeline::kMaxJobs));
  batch->add_option("--shard", shard, "K/N: only runs i with i % N == K-1 (1-based K)");
  batch->add_flag("--dry-run", dryRun, "List the runs and their status; render nothing");
  batch->add_flag("--verify", verify, "Skip a run only if its files match their checksums");
  batch->add_flag("-q,--quiet", quiet, "No progress output (the summary is still printed)");

  CLI::App* info = app.add_subcommand("info", "Describe a glTF scene as tofsim loads it");
  std::string scenePath;
  info->add_option("scene", scenePath, "glTF file (.gltf or .glb)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  tofsim::installInterruptHandlers();
  return tofsim::pipeline::exitCodeOf([&] {
    if (render->parsed()) {
      return runRenderCommand(configPath, outputDir, sets, quiet, strict, platform, renderer,
                              backend, batchRun);
    }
    if (compareCommand->parsed()) return runCompareCommand(dirA, dirB, outputDir);
    if (sense->parsed()) return runSenseCommand(configPath, volumeDir, outputDir, sets, quiet);
    if (validate->parsed()) return runValidateCommand(configPath, sets, strict);
    if (batch->parsed()) {
      return runBatchCommand(configPath, sets, jobs, shard, dryRun, verify, quiet);
    }
    if (info->parsed()) return runInfoCommand(scenePath);
    return 2;
  });
}
