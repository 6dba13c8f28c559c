// Slurm through its own commands (sbatch, squeue, scancel), each run as a child process with
// its arguments as they are: no shell in between, so no path or option needs quoting.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace veduta {

struct ProgramResult {
    int status = 0;  // the exit status, or 128 + the signal that ended it
    std::string out, err;
};

// The program `name` as the shell would find it on PATH; nothing where it is not there.
std::optional<std::filesystem::path> findOnPath(const std::string &name);

// Runs argv[0] (found on PATH) with standard input from /dev/null and waits for it.
// std::runtime_error when it cannot be started.
ProgramResult runProgram(const std::vector<std::string> &argv);

// `sbatch --parsable OPTIONS SCRIPT`: the job id. std::runtime_error with sbatch's message.
std::string submitBatchJob(const std::filesystem::path &script, const std::vector<std::string> &options);

// `scancel ID`, for cleaning up after a half-done submission; its failure is only reported.
void cancelJob(const std::string &id);

// A job or array task that the controller still knows, running or recently ended.
struct QueuedJob {
    std::string name;
    int arrayTask = -1;  // -1 for a job that is not part of an array
    std::string state;   // squeue's %T: PENDING, RUNNING, COMPLETED, FAILED, …
    std::string reason;  // squeue's %r: Dependency, DependencyNeverSatisfied, None, …
};

// Every job and array task with one of these names (squeue --states=all, one line per task).
// std::runtime_error with squeue's message when the controller cannot be asked.
std::vector<QueuedJob> queuedJobs(const std::vector<std::string> &names);

// A state in which the job is still to run or running (PENDING, RUNNING, REQUEUED, …).
bool isLiveState(const std::string &state);

}  // namespace veduta
