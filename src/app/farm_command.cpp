// `veduta farm submit` and `veduta farm status`: one render split into a Slurm job array of
// tiles or sample ranges, merged by a job that waits for them (docs/farm.md).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/exr_options.h"
#include "app/farm_job.h"
#include "app/farm_scripts.h"
#include "app/farm_split.h"
#include "app/farm_status.h"
#include "app/number_option.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "app/slurm.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/program_folder.h"
#include "io/output_files.h"

namespace veduta {

namespace fs = std::filesystem;

namespace {

struct SubmitArgs {
    std::string scene, output, jobDir;
    unsigned tiles = 0, sampleRanges = 0;
    SlurmRequest slurm;
    double checkpointEvery = kDefaultCheckpointSeconds;
    bool dryRun = false;
    // Passed through to every task's `veduta render`: the options that decide the image, and
    // what its EXR holds (the merge keeps the parts' passes, types and codec).
    std::optional<uint32_t> spp, seed, maxDepth, minSamples;
    std::string resolution, noiseThreshold;
    ExrArgs exr;
};

// What the tasks need of the scene before anything is rendered: the image size and the samples.
struct ImageSize {
    int width = 0, height = 0;
    uint32_t spp = 0;
};

ImageSize imageSize(const SubmitArgs &args) {
    SceneDescription description = loadSceneDescription(args.scene);
    applyResolution(args.resolution, description.camera);
    return {description.camera.width, description.camera.height,
            args.spp ? *args.spp : description.settings.samplesPerPixel};
}

// Each task's own options. Too many tiles or ranges is a usage error: the command line asks
// for what the image cannot give.
std::vector<std::vector<std::string>> taskOptions(const SubmitArgs &args, const ImageSize &size) {
    std::vector<std::vector<std::string>> tasks;
    try {
        if (args.tiles) {
            for (const PixelWindow &w : splitIntoTiles(size.width, size.height, int(args.tiles))) {
                tasks.push_back({"--region", std::to_string(w.x0), std::to_string(w.y0), std::to_string(w.x1),
                                 std::to_string(w.y1)});
            }
        } else {
            for (const SampleRange &r : splitSamples(size.spp, args.sampleRanges)) {
                tasks.push_back({"--spp", std::to_string(r.samples), "--sample-offset", std::to_string(r.offset)});
            }
        }
    } catch (const std::invalid_argument &e) {
        throw CLI::ValidationError(args.tiles ? "--tiles" : "--sample-ranges", e.what());
    }
    return tasks;
}

// veduta merge weighs each part's pixels by their SampleCount, so the parts keep that pass
// whatever --passes leaves out (and the merged image with them).
ExrArgs partExr(ExrArgs exr) {
    if (std::find(exr.passes.begin(), exr.passes.end(), "SampleCount") == exr.passes.end())
        exr.passes.push_back("SampleCount");
    return exr;
}

std::vector<std::string> renderOptions(const SubmitArgs &args, const ImageSize &size) {
    std::vector<std::string> options;
    auto add = [&options](const char *option, const std::string &value) {
        if (!value.empty()) options.insert(options.end(), {option, value});
    };
    auto number = [](const std::optional<uint32_t> &n) { return n ? std::to_string(*n) : std::string(); };
    if (args.tiles) add("--spp", std::to_string(size.spp));  // a sample range's task names its own
    add("--res", args.resolution);
    add("--seed", number(args.seed));
    add("--max-depth", number(args.maxDepth));
    add("--noise-threshold", args.noiseThreshold);
    add("--min-spp", number(args.minSamples));
    std::vector<std::string> exr = exrArguments(partExr(args.exr));
    options.insert(options.end(), exr.begin(), exr.end());
    return options;
}

// Slurm job names are matched by `veduta farm status`; the folder's hash keeps two jobs of
// the same output name apart.
std::string jobName(const fs::path &output, const fs::path &folder) {
    std::string stem = output.stem().string();
    for (char &c : stem) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    }
    return fmt::format("veduta-{}-{:08x}", stem, uint32_t(std::hash<std::string>{}(folder.string())));
}

// The tasks run this very program, whatever name or link it was started by.
fs::path programForTasks() {
    std::optional<fs::path> self = runningProgram();
    if (!self) throw std::runtime_error("cannot find the running program: /proc/self/exe is not readable");
    return *self;
}

FarmJob planJob(const SubmitArgs &args, const ImageSize &size, std::vector<std::vector<std::string>> tasks) {
    FarmJob job;
    job.output = fs::absolute(args.output.empty() ? defaultOutput(args.scene, ".exr") : args.output).lexically_normal();
    job.folder = fs::absolute(args.jobDir.empty() ? job.output.string() + ".farm" : args.jobDir).lexically_normal();
    job.name = jobName(job.output, job.folder);
    job.program = programForTasks();
    if (!args.scene.empty()) job.scene = fs::absolute(args.scene).lexically_normal();
    job.renderOptions = renderOptions(args, size);
    job.tasks = std::move(tasks);
    job.checkpointEvery = args.checkpointEvery;
    job.slurm = args.slurm;
    return job;
}

// A folder that holds a submitted job keeps it: its parts and ids must not be mixed with another's.
void checkJobFolder(const FarmJob &job) {
    if (fs::exists(jobFilePath(job.folder)) && !readJobFile(job.folder).arrayJobId.empty()) {
        throw InputError(
            FileLoc{job.folder.string()},
            "holds a submitted farm job already (see its farm.job); remove it or choose another --job-dir");
    }
    checkSbatchValues(job);
}

void writeText(const fs::path &file, const std::string &text) { writeBytesAtomically(file, text.data(), text.size()); }

void writeJobFolder(const FarmJob &job) {
    for (const char *folder : {"parts", "logs", "status"}) fs::create_directories(job.folder / folder);
    prepareOutputFile(job.output);
    writeText(taskScriptPath(job), taskScript(job));
    writeText(mergeScriptPath(job), mergeScript(job));
    writeText(jobFilePath(job.folder), jobFileText(job));
}

// The array first, then the merge after all its tasks; a merge that cannot be submitted takes
// the array back, so that no job runs whose parts nothing would merge.
void submit(FarmJob &job) {
    job.arrayJobId = submitBatchJob(taskScriptPath(job), {});
    try {
        job.mergeJobId =
            submitBatchJob(mergeScriptPath(job),
                           {fmt::format("--dependency=afterok:{}", job.arrayJobId), "--kill-on-invalid-dep=yes"});
    } catch (...) {
        cancelJob(job.arrayJobId);
        throw;
    }
}

void runSubmit(const SubmitArgs &args, const ImageSize &size, FarmJob &job) {
    checkJobFolder(job);
    // The job file is there before anything runs: `veduta farm status` finds the jobs by name.
    writeJobFolder(job);
    if (args.dryRun) {
        std::printf(
            "wrote %s and %s: %zu tasks of a %dx%d image at %u spp; submit with\n  id=$(sbatch --parsable %s)\n"
            "  sbatch --dependency=afterok:$id --kill-on-invalid-dep=yes %s\n",
            taskScriptPath(job).c_str(), mergeScriptPath(job).c_str(), job.tasks.size(), size.width, size.height,
            size.spp, shellQuoted(taskScriptPath(job).string()).c_str(),
            shellQuoted(mergeScriptPath(job).string()).c_str());
        return;
    }
    submit(job);
    writeText(jobFilePath(job.folder), jobFileText(job));
    std::printf("submitted job %s (%zu tasks) and merge job %s: veduta farm status %s\n", job.arrayJobId.c_str(),
                job.tasks.size(), job.mergeJobId.c_str(), shellQuoted(job.folder.string()).c_str());
}

// The usage errors come first (exit 2), then the scene is read (exit 1), then files are written.
void submitCommand(const SubmitArgs &args, int &exitCode) {
    if (!args.dryRun && !findOnPath("sbatch")) {
        throw CLI::ValidationError("sbatch",
                                   "not found on PATH: install Slurm's commands (Debian: slurm-client, or "
                                   "slurm-wlm for a whole cluster), or write the scripts only with --dry-run");
    }
    ImageSize size;
    exitCode = runGuarded([&] { size = imageSize(args); });
    if (exitCode != kExitOk) return;
    std::vector<std::vector<std::string>> tasks = taskOptions(args, size);
    std::optional<FarmJob> job;
    exitCode = runGuarded([&] { job = planJob(args, size, std::move(tasks)); });
    if (exitCode == kExitOk) exitCode = runGuarded([&] { runSubmit(args, size, *job); });
}

int runStatus(const std::string &folder) {
    FarmJob job = readJobFile(folder);
    std::vector<QueuedJob> queued;
    if (!fs::exists(job.output)) {
        if (!findOnPath("squeue")) {
            throw std::runtime_error("squeue not found on PATH: install Slurm's commands (Debian: slurm-client)");
        }
        queued = queuedJobs({job.name, mergeJobName(job)});
    }
    FarmStatus status = farmStatus(job, queued);
    for (const std::string &line : status.lines) std::printf("%s\n", line.c_str());
    return status.exitCode;
}

void addSubmitCommand(CLI::App &farm, int &exitCode) {
    auto args = std::make_shared<SubmitArgs>();
    CLI::App *cmd = farm.add_subcommand(
        "submit", "Write a Slurm job array that renders the parts and a job that merges them, and submit both");
    addSceneArgument(*cmd, args->scene);
    CLI::Option *tiles = cmd->add_option("--tiles", args->tiles, "Split the image into N rectangles, one task each")
                             ->check(CLI::Range(1u, 1u << 30));
    CLI::Option *ranges = cmd->add_option("--sample-ranges", args->sampleRanges,
                                          "Split the samples per pixel into K ranges, one task each")
                              ->check(CLI::Range(1u, 1u << 24));
    tiles->excludes(ranges);
    cmd->add_option("-o,--output", args->output, "The merged EXR [renders/<scene name>.exr]")
        ->check(fileWithExtension(".exr"));
    cmd->add_option("--job-dir", args->jobDir, "Folder of the scripts, parts, logs and job file [<output>.farm]");
    cmd->add_option("--partition", args->slurm.partition, "Slurm partition (sbatch --partition)");
    cmd->add_option("--account", args->slurm.account, "Slurm account (sbatch --account)");
    cmd->add_option("--time", args->slurm.time, "Time limit of each task and of the merge (sbatch --time)");
    cmd->add_option("--cpus-per-task", args->slurm.cpusPerTask, "CPUs of each task, its render's threads")
        ->check(CLI::Range(1u, 4096u));
    cmd->add_option("--mem", args->slurm.memory, "Memory of each task and of the merge (sbatch --mem, e.g. 16G)");
    cmd->add_option("--max-parallel", args->slurm.maxParallel, "At most M tasks at once (the array's %M)")
        ->check(CLI::Range(1u, 1u << 20));
    cmd->add_option("--checkpoint-every", args->checkpointEvery,
                    "Seconds between a task's checkpoints, from which a requeued task resumes [300]")
        ->check(finiteIn(1, 1e9));
    cmd->add_option("--sbatch-arg", args->slurm.extra,
                    "A further #SBATCH option for both scripts, e.g. --sbatch-arg=--qos=long")
        ->allow_extra_args(false);
    cmd->add_flag("--dry-run", args->dryRun, "Write the scripts and the job file, submit nothing");
    cmd->add_option("--spp,--samples", args->spp, "Samples per pixel (overrides the scene)")
        ->check(CLI::Range(1u, 1u << 24));
    addResolutionOption(*cmd, args->resolution);
    cmd->add_option("--seed", args->seed, "Seed of every random choice (as veduta render --seed)");
    cmd->add_option("--max-depth", args->maxDepth, "Longest path, in bounces (overrides the scene)")
        ->check(CLI::Range(1u, 1024u));
    // Adaptive sampling stops each range by its own samples, so ranges would not add up.
    cmd->add_option("--noise-threshold", args->noiseThreshold, "Adaptive sampling, as veduta render (tiles only)")
        ->check(finiteIn(0, 1e6))
        ->excludes(ranges);
    cmd->add_option("--min-spp", args->minSamples, "Adaptive sampling, as veduta render (tiles only)")
        ->check(CLI::Range(1u, 1u << 24))
        ->excludes(ranges);
    addExrOptions(*cmd, args->exr);
    cmd->callback([tiles, ranges, args, &exitCode] {
        if (!*tiles && !*ranges) throw CLI::RequiredError("--tiles or --sample-ranges");
        checkCompression(args->exr);
        submitCommand(*args, exitCode);
    });
}

void addStatusCommand(CLI::App &farm, int &exitCode) {
    auto folder = std::make_shared<std::string>();
    CLI::App *cmd = farm.add_subcommand(
        "status", "One line per task and the merge, and a summary; exit 0 merged, 1 failed, 4 still running");
    cmd->add_option("job-dir", *folder, "The job folder `veduta farm submit` wrote")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->callback([folder, &exitCode] {
        int code = kExitOk;
        exitCode = runGuarded([&] { code = runStatus(*folder); });
        if (exitCode == kExitOk) exitCode = code;
    });
}

}  // namespace

void addFarmCommand(CLI::App &app, int &exitCode) {
    CLI::App *farm = app.add_subcommand("farm", "Render one image on a Slurm cluster: tiles or sample ranges, merged");
    farm->require_subcommand(1);
    addSubmitCommand(*farm, exitCode);
    addStatusCommand(*farm, exitCode);
}

}  // namespace veduta
