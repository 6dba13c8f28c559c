#include "app/farm_status.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/commands.h"

namespace veduta {

namespace fs = std::filesystem;

namespace {

std::string lowercase(std::string text) {
    for (char &c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::string describe(const QueuedJob &job) {
    bool reasonSays = !job.reason.empty() && job.reason != "None";
    return reasonSays ? fmt::format("{} ({})", lowercase(job.state), job.reason) : lowercase(job.state);
}

// The exit status in the file; -1 for a file that is there but holds none.
std::optional<int> recordedFailure(const fs::path &file) {
    std::ifstream in(file);
    int status = 0;
    if (in >> status) return status;
    return in.is_open() ? std::optional<int>(-1) : std::nullopt;
}

StepFacts factsOf(const fs::path &result, const fs::path &failure, const std::vector<QueuedJob> &queued,
                  bool submitted) {
    return {fs::exists(result), recordedFailure(failure), queued, submitted};
}

std::vector<QueuedJob> entriesOf(const std::vector<QueuedJob> &queued, const std::string &name, int arrayTask) {
    std::vector<QueuedJob> entries;
    std::copy_if(queued.begin(), queued.end(), std::back_inserter(entries),
                 [&](const QueuedJob &q) { return q.name == name && q.arrayTask == arrayTask; });
    return entries;
}

}  // namespace

StepStatus stepStatus(const StepFacts &facts) {
    if (facts.resultExists) return {StepProgress::Done, "done"};
    auto live = std::find_if(facts.queued.begin(), facts.queued.end(), [](auto &q) { return isLiveState(q.state); });
    if (live != facts.queued.end()) {
        // A merge whose tasks did not all succeed stays pending for ever unless Slurm cancels it.
        bool never = live->reason == "DependencyNeverSatisfied";
        return {never ? StepProgress::Failed : StepProgress::Waiting, describe(*live)};
    }
    if (facts.recordedFailure)
        return {StepProgress::Failed, fmt::format("failed with exit status {}", *facts.recordedFailure)};
    if (!facts.queued.empty()) {
        const QueuedJob &last = facts.queued.back();
        return {StepProgress::Failed, last.state == "COMPLETED" ? "completed without its file" : describe(last)};
    }
    return {StepProgress::Failed, facts.submitted ? "lost: not in Slurm's queue and not done" : "not submitted"};
}

FarmStatus farmStatus(const FarmJob &job, const std::vector<QueuedJob> &queued) {
    const bool submitted = !job.arrayJobId.empty();
    FarmStatus status;
    size_t done = 0, failed = 0;
    for (size_t i = 0; i < job.tasks.size(); ++i) {
        StepStatus step =
            stepStatus(factsOf(partPath(job, i), failurePath(job, i), entriesOf(queued, job.name, int(i)), submitted));
        done += step.progress == StepProgress::Done;
        failed += step.progress == StepProgress::Failed;
        std::string log =
            step.progress == StepProgress::Failed ? fmt::format(", log {}", logPath(job, i).string()) : "";
        status.lines.push_back(fmt::format("task {}: {}: {}{}", i, fmt::join(job.tasks[i], " "), step.text, log));
    }
    StepStatus merge =
        stepStatus(factsOf(job.output, mergeFailurePath(job), entriesOf(queued, mergeJobName(job), -1), submitted));
    std::string log = merge.progress == StepProgress::Failed ? fmt::format(", log {}", mergeLogPath(job).string()) : "";
    status.lines.push_back(fmt::format("merge: {}: {}{}", job.output.string(), merge.text, log));
    status.lines.push_back(fmt::format("{} tasks: {} done, {} failed, {} queued or running; merge {}", job.tasks.size(),
                                       done, failed, job.tasks.size() - done - failed, merge.text));
    if (merge.progress == StepProgress::Done) {
        status.exitCode = kExitOk;
    } else if (failed > 0 || merge.progress == StepProgress::Failed) {
        status.exitCode = kExitBadInput;
    }
    return status;
}

}  // namespace veduta
