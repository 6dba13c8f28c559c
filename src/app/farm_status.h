// What `veduta farm status` makes of a job: each task's and the merge's state from the files
// in the job folder and from what Slurm's controller still knows (squeue, which works without
// an accounting database but forgets ended jobs after MinJobAge), and the exit code for scripts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/farm_job.h"
#include "app/slurm.h"

namespace veduta {

// `veduta farm status` exits 0 once the merged image exists, kExitBadInput when a task or the
// merge failed or was lost, and this while everything that is not done is still queued or running.
constexpr int kExitInProgress = 4;

enum class StepProgress { Done, Waiting, Failed };

struct StepStatus {
    StepProgress progress = StepProgress::Waiting;
    std::string text;  // "done", "running", "pending (Dependency)", "failed with exit status 1", …
};

// What is known of one task, or of the merge.
struct StepFacts {
    bool resultExists = false;           // its part, or the merged image
    std::optional<int> recordedFailure;  // the exit status its script left in status/
    std::vector<QueuedJob> queued;       // its entries in squeue, oldest first
    bool submitted = true;               // false for a --dry-run job
};

StepStatus stepStatus(const StepFacts &facts);

struct FarmStatus {
    std::vector<std::string> lines;  // one per task, then the merge, then the summary
    int exitCode = kExitInProgress;
};

// `queued`: squeue's entries for the job's two names (empty when not asked: the image exists).
FarmStatus farmStatus(const FarmJob &job, const std::vector<QueuedJob> &queued);

}  // namespace veduta
