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
#include "tofsim/pipeline/CompareRun.h"
#include "tofsim/pipeline/ExitCode.h"
#include "tofsim/pipeline/OutputEstimate.h"
#include "tofsim/pipeline/PresetList.h"
#include "tofsim/pipeline/RenderRun.h"
#include "tofsim/pipeline/RunContentKey.h"
#include "tofsim/pipeline/SceneInfo.h"
#include "tofsim/pipeline/SenseRun.h"
#include "tofsim/pipeline/ValidateRun.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Interrupt.h"
#include "ViewCommand.h"

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
  pipeline::validateRun(config);  // render's checks before rendering; notes on stderr
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

int runPresetsCommand(const std::string& name) {
  std::fputs(pipeline::describePresets(name).c_str(), stdout);
  return 0;
}

// Every option of every subcommand: CLI11 writes into these.
struct Args {
  std::string configPath, outputDir, platform, volumeDir, renderer, backend, dirA, dirB;
  std::string batchRun, shard, scenePath, presetName;
  std::vector<std::string> sets;
  bool quiet = false, strict = false, dryRun = false, verify = false;
  int jobs = 1;
  cli::ViewArgs view;
};

struct Commands {
  CLI::App *render, *sense, *compare, *validate, *batch, *info, *presets, *view;
};

const char* kStrictHelp =
    "Light cut off by the time axis or a sensor window is an error (= --set render.strict=true)";
const char* kSetHelp = "Override a config key: key.path=value (repeatable)";

// -o "" would silently mean "no -o" (the config's output.directory, or A):
// an empty folder name is a usage error naming the option.
CLI::Validator notEmpty() {
  return CLI::Validator(
      [](const std::string& s) { return s.empty() ? "must not be empty" : std::string(); }, "",
      "NOT_EMPTY");
}

CLI::App* addRender(CLI::App& app, Args& a) {
  CLI::App* render = app.add_subcommand("render", "Render a config's transient volume and outputs");
  render->add_option("config", a.configPath, "YAML config file")->required();
  render->add_option("-o,--output", a.outputDir, "Output directory (default: output.directory)")
      ->check(notEmpty());
  render->add_option("--set", a.sets, kSetHelp);
  render->add_flag("-q,--quiet", a.quiet, "No progress output");
  render->add_flag("--strict", a.strict, kStrictHelp);
  render->add_option("--egl-platform", a.platform,
                     "auto | surfaceless | device (default: $TOFSIM_EGL_PLATFORM or auto)");
  render->add_option("--renderer", a.renderer, "ir | reference (same as --set render.renderer=...)")
      ->check(CLI::IsMember({"ir", "reference"}));
  render->add_option("--backend", a.backend, "auto | gl | cpu (same as --set render.backend=...)")
      ->check(CLI::IsMember({"auto", "gl", "cpu"}));
  // Internal, for `tofsim batch`: write the run's manifest.json last.
  render->add_option("--batch-run", a.batchRun, "Batch run name (internal)")->group("");
  return render;
}

CLI::App* addSense(CLI::App& app, Args& a) {
  CLI::App* sense = app.add_subcommand(
      "sense", "Run a config's sensors on a saved render (uses only sensors: and render.seed)");
  sense->add_option("config", a.configPath, "YAML config file")->required();
  sense->add_option("--volume", a.volumeDir, "Folder of a render: transient.npy + transient.json")
      ->required();
  sense->add_option("-o,--output", a.outputDir, "Output directory (default: the --volume folder)")
      ->check(notEmpty());
  sense->add_option("--set", a.sets, kSetHelp);
  sense->add_flag("-q,--quiet", a.quiet, "No progress output");
  return sense;
}

CLI::App* addCompare(CLI::App& app, Args& a) {
  CLI::App* compare = app.add_subcommand(
      "compare", "Error metrics of render A against reference B (two output directories)");
  compare->add_option("a", a.dirA, "Output directory under test")->required();
  compare->add_option("b", a.dirB, "Output directory of the reference")->required();
  compare
      ->add_option("-o,--output", a.outputDir, "Where to write the comparison files (default: A)")
      ->check(notEmpty());
  return compare;
}

CLI::App* addValidate(CLI::App& app, Args& a) {
  CLI::App* validate = app.add_subcommand("validate", "Check a config without rendering");
  validate->add_option("config", a.configPath, "YAML config file")->required();
  validate->add_option("--set", a.sets, kSetHelp);
  validate->add_flag("--strict", a.strict, kStrictHelp);
  return validate;
}

CLI::App* addBatch(CLI::App& app, Args& a) {
  CLI::App* batch = app.add_subcommand(
      "batch", "Run a batch file's runs and sweeps, each into <output>/<run name>/ (resumable)");
  batch->add_option("batch", a.configPath, "Batch YAML file (configs/README.md, Batch files)")
      ->required();
  batch->add_option("--set", a.sets, "Override a config key in every run: key.path=value");
  batch->add_option("-j,--jobs", a.jobs,
                    "Runs at once, each on a worker process that keeps its renderer (default 1)")
      ->check(CLI::Range(1, tofsim::pipeline::kMaxJobs));
  batch->add_option("--shard", a.shard, "K/N: only runs i with i % N == K-1 (1-based K)");
  batch->add_flag("--dry-run", a.dryRun, "List the runs and their status; render nothing");
  batch->add_flag("--verify", a.verify, "Skip a run only if its files match their checksums");
  batch->add_flag("-q,--quiet", a.quiet, "No progress output (the summary is still printed)");
  return batch;
}

CLI::App* addInfo(CLI::App& app, Args& a) {
  CLI::App* info = app.add_subcommand("info", "Describe a glTF scene as tofsim loads it");
  info->add_option("scene", a.scenePath, "glTF file (.gltf or .glb)")->required();
  return info;
}

CLI::App* addPresets(CLI::App& app, Args& a) {
  CLI::App* presets = app.add_subcommand(
      "presets", "List the device presets (SPAD, CW-ToF, lidar): the values each sets and their sources");
  presets->add_option("name", a.presetName, "Only this preset");
  return presets;
}

// Under every help: where the docs and a first config are.
const char* kDocsFooter =
    "Docs: README.md (quick start, outputs), configs/README.md (every config key),\n"
    "sensors/README.md (sensor models). A first run:\n"
    "  tofsim render configs/cornell_box.yaml -o out/cornell_box";

// The one subcommand parsed.
int dispatch(const Commands& c, const Args& a) {
  if (c.render->parsed()) {
    return runRenderCommand(a.configPath, a.outputDir, a.sets, a.quiet, a.strict, a.platform,
                            a.renderer, a.backend, a.batchRun);
  }
  if (c.compare->parsed()) return runCompareCommand(a.dirA, a.dirB, a.outputDir);
  if (c.sense->parsed())
    return runSenseCommand(a.configPath, a.volumeDir, a.outputDir, a.sets, a.quiet);
  if (c.validate->parsed()) return runValidateCommand(a.configPath, a.sets, a.strict);
  if (c.batch->parsed()) {
    return runBatchCommand(a.configPath, a.sets, a.jobs, a.shard, a.dryRun, a.verify, a.quiet);
  }
  if (c.info->parsed()) return runInfoCommand(a.scenePath);
  if (c.presets->parsed()) return runPresetsCommand(a.presetName);
  if (c.view->parsed()) return cli::runViewCommand(a.view);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tofsim: time-of-flight sensor simulator (transient instant radiosity)"};
  app.set_version_flag("--version", std::string("tofsim ") + tofsim::pipeline::kVersion);
  app.require_subcommand(1);
  Args args;
  const Commands commands{addRender(app, args),   addSense(app, args), addCompare(app, args),
                          addValidate(app, args), addBatch(app, args), addInfo(app, args),
                          addPresets(app, args),  cli::addView(app, args.view)};
  app.footer(kDocsFooter);
  for (CLI::App* sub : app.get_subcommands({})) sub->footer(kDocsFooter);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  tofsim::installInterruptHandlers();
  return tofsim::pipeline::exitCodeOf([&] { return dispatch(commands, args); });
}
