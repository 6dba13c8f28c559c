#include "app/farm_scripts.h"

#include <fmt/format.h>

#include "core/error.h"

namespace veduta {

namespace {

std::string quotedWords(const std::vector<std::string> &words) {
    std::string text;
    for (const std::string &word : words) {
        if (!text.empty()) text += ' ';
        text += shellQuoted(word);
    }
    return text;
}

// The requests both scripts share; the tasks' CPUs are theirs alone (the merge reads files).
std::string requestLines(const SlurmRequest &r) {
    std::string lines;
    auto line = [&lines](const char *option, const std::string &value) {
        if (!value.empty()) lines += fmt::format("#SBATCH --{}={}\n", option, value);
    };
    line("partition", r.partition);
    line("account", r.account);
    line("time", r.time);
    line("mem", r.memory);
    for (const std::string &extra : r.extra) fmt::format_to(std::back_inserter(lines), "#SBATCH {}\n", extra);
    return lines;
}

// Records a failed run's exit status where `veduta farm status` finds it after Slurm has
// forgotten the job; written under a temporary name and renamed, as every file here.
std::string recordFailure() {
    return "status=$?\n"
           "if [ \"$status\" != 0 ]; then echo \"$status\" >\"$failed.tmp\" && mv \"$failed.tmp\" \"$failed\"; fi\n"
           "exit \"$status\"\n";
}

std::string taskCases(const FarmJob &job) {
    std::string cases;
    for (size_t i = 0; i < job.tasks.size(); ++i)
        cases += fmt::format("{}) task=({}) ;;\n", i, quotedWords(job.tasks[i]));
    return cases + "*) echo \"veduta farm: this job has no task $index\" >&2; exit 2 ;;\n";
}

}  // namespace

std::string shellQuoted(const std::string &text) {
    std::string quoted = "'";
    for (char c : text) {
        if (c == '\'') quoted += "'\\''";
        else quoted += c;
    }
    quoted += '\'';
    return quoted;
}

void checkSbatchValues(const FarmJob &job) {
    if (job.folder.string().find_first_of("%\"\\\n") != std::string::npos) {
        throw InputError(FileLoc{"--job-dir"},
                         fmt::format("'{}' holds a %, \", \\ or line break, which Slurm's log file names cannot "
                                     "take; choose another job folder",
                                     job.folder.string()));
    }
    const SlurmRequest &r = job.slurm;
    for (const std::string *value : {&r.partition, &r.account, &r.time, &r.memory}) {
        if (value->find('\n') != std::string::npos)
            throw InputError(FileLoc{"sbatch option"}, "a value holds a line break");
    }
    for (const std::string &extra : r.extra) {
        if (!extra.starts_with('-') || extra.find('\n') != std::string::npos) {
            throw InputError(
                FileLoc{"--sbatch-arg"},
                fmt::format("'{}' is no sbatch option (one option per --sbatch-arg, e.g. --qos=long)", extra));
        }
    }
}

std::string taskScript(const FarmJob &job) {
    std::string throttle = job.slurm.maxParallel ? fmt::format("%{}", job.slurm.maxParallel) : "";
    std::string text = fmt::format(
        "#!/bin/bash\n"
        "# veduta farm: the render tasks of {0}, written by `veduta farm submit`.\n"
        "# Task N renders part N; run one task again with: sbatch --array=N {1}\n"
        "#SBATCH --job-name={2}\n"
        "#SBATCH --array=0-{3}{4}\n"
        "#SBATCH --output=\"{5}/task-%a.log\"\n"
        "#SBATCH --open-mode=append\n"
        "#SBATCH --requeue\n",
        job.folder.string(), taskScriptPath(job).string(), job.name, job.tasks.size() - 1, throttle,
        (job.folder / "logs").string());
    if (job.slurm.cpusPerTask) text += fmt::format("#SBATCH --cpus-per-task={}\n", job.slurm.cpusPerTask);
    text += requestLines(job.slurm);
    text +=
        "set -u\n"
        "index=${SLURM_ARRAY_TASK_ID:?run this script with sbatch, as a job array}\n"
        "case $index in\n" +
        taskCases(job) + "esac\n";
    text += fmt::format("part={}/part-$index.exr\nfailed={}/task-$index.failed\n",
                        shellQuoted((job.folder / "parts").string()), shellQuoted((job.folder / "status").string()));
    text +=
        "rm -f \"$failed\"\n"
        "threads=()\n"
        "if [ -n \"${SLURM_CPUS_PER_TASK:-}\" ]; then threads=(--threads \"$SLURM_CPUS_PER_TASK\"); fi\n"
        "# Checkpoints and --resume: a task that is preempted or requeued continues where it stood.\n";
    std::vector<std::string> render{job.program.string(), "render"};
    if (!job.scene.empty()) render.push_back(job.scene.string());
    render.insert(render.end(), job.renderOptions.begin(), job.renderOptions.end());
    text += quotedWords(render) +
        fmt::format(" \"${{task[@]}}\" \"${{threads[@]}}\" --checkpoint-every {} --resume -o \"$part\"\n",
                    job.checkpointEvery);
    return text + recordFailure();
}

std::string mergeScript(const FarmJob &job) {
    std::string text = fmt::format(
        "#!/bin/bash\n"
        "# veduta farm: merges the parts of {0} into {1}; submitted to run once every task has succeeded.\n"
        "#SBATCH --job-name={2}\n"
        "#SBATCH --output=\"{3}\"\n"
        "#SBATCH --open-mode=append\n",
        job.folder.string(), job.output.string(), mergeJobName(job), mergeLogPath(job).string());
    text += requestLines(job.slurm);
    text += fmt::format("set -u\nfailed={}\nrm -f \"$failed\"\n", shellQuoted(mergeFailurePath(job).string()));
    std::vector<std::string> merge{job.program.string(), "merge", job.output.string()};
    for (size_t i = 0; i < job.tasks.size(); ++i) merge.push_back(partPath(job, i).string());
    return text + quotedWords(merge) + "\n" + recordFailure();
}

}  // namespace veduta
