// A render farm job as `veduta farm submit` lays it out in its folder and `veduta farm status`
// reads it back: the tasks, their parts, the job ids and the file that records them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace veduta {

// What Slurm is asked for, passed through to the scripts' #SBATCH lines; empty: Slurm's default.
struct SlurmRequest {
    std::string partition, account, time, memory;
    unsigned cpusPerTask = 0;        // 0: Slurm's default
    unsigned maxParallel = 0;        // the array's %M throttle; 0: none
    std::vector<std::string> extra;  // further sbatch options, each as one argument (--sbatch-arg)
};

// Seconds between a task's checkpoints unless --checkpoint-every says otherwise: at most this
// much work is lost when a task is preempted, for a checkpoint write every few minutes.
constexpr double kDefaultCheckpointSeconds = 300;

struct FarmJob {
    std::filesystem::path folder;                 // absolute, as every path here, so that any node finds it
    std::string name;                             // the Slurm job name of the tasks; the merge's adds "-merge"
    std::filesystem::path program;                // the veduta that submitted, which the tasks run too
    std::filesystem::path scene;                  // empty: the built-in default scene
    std::filesystem::path output;                 // the merged EXR
    std::vector<std::string> renderOptions;       // every task's: --spp, --res, --seed, …
    std::vector<std::vector<std::string>> tasks;  // each task's own: --region … or --spp … --sample-offset …
    double checkpointEvery = kDefaultCheckpointSeconds;
    SlurmRequest slurm;
    std::string arrayJobId, mergeJobId;  // empty until submitted
};

std::filesystem::path jobFilePath(const std::filesystem::path &folder);  // folder/farm.job
std::filesystem::path partPath(const FarmJob &job, size_t task);         // folder/parts/part-<task>.exr
std::filesystem::path taskScriptPath(const FarmJob &job);                // folder/render.sbatch
std::filesystem::path mergeScriptPath(const FarmJob &job);               // folder/merge.sbatch
std::filesystem::path logPath(const FarmJob &job, size_t task);          // folder/logs/task-<task>.log
std::filesystem::path mergeLogPath(const FarmJob &job);                  // folder/logs/merge.log
// Where a task (or the merge) that failed leaves its exit status, which outlives Slurm's memory.
std::filesystem::path failurePath(const FarmJob &job, size_t task);  // folder/status/task-<task>.failed
std::filesystem::path mergeFailurePath(const FarmJob &job);          // folder/status/merge.failed
std::string mergeJobName(const FarmJob &job);

// The job file: `key=value` lines, what `veduta farm status` needs and what a person looks up.
std::string jobFileText(const FarmJob &job);
// The job file in `folder`, read back (renderOptions and slurm are not kept there).
// InputError when it is missing or not a farm job file.
FarmJob readJobFile(const std::filesystem::path &folder);

}  // namespace veduta
