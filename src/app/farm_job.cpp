#include "app/farm_job.h"

#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.h"

namespace veduta {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> words(const std::string &text) {
    std::vector<std::string> list;
    std::istringstream in(text);
    for (std::string word; in >> word;) list.push_back(word);
    return list;
}

// A key the job file must have; `file` names it in the message.
const std::string &required(const std::map<std::string, std::string> &values, const std::string &key,
                            const fs::path &file) {
    auto found = values.find(key);
    if (found == values.end())
        throw InputError(FileLoc{file.string()}, fmt::format("not a veduta farm job file: no {}", key));
    return found->second;
}

}  // namespace

fs::path jobFilePath(const fs::path &folder) { return folder / "farm.job"; }
fs::path partPath(const FarmJob &job, size_t task) { return job.folder / "parts" / fmt::format("part-{}.exr", task); }
fs::path taskScriptPath(const FarmJob &job) { return job.folder / "render.sbatch"; }
fs::path mergeScriptPath(const FarmJob &job) { return job.folder / "merge.sbatch"; }
fs::path logPath(const FarmJob &job, size_t task) { return job.folder / "logs" / fmt::format("task-{}.log", task); }
fs::path mergeLogPath(const FarmJob &job) { return job.folder / "logs" / "merge.log"; }
fs::path failurePath(const FarmJob &job, size_t task) {
    return job.folder / "status" / fmt::format("task-{}.failed", task);
}
fs::path mergeFailurePath(const FarmJob &job) { return job.folder / "status" / "merge.failed"; }
std::string mergeJobName(const FarmJob &job) { return job.name + "-merge"; }

std::string jobFileText(const FarmJob &job) {
    std::string text = "# veduta farm job: veduta farm status reads this file\n";
    text += fmt::format("name={}\nprogram={}\nscene={}\noutput={}\n", job.name, job.program.string(),
                        job.scene.string(), job.output.string());
    text += fmt::format("array_job={}\nmerge_job={}\ntasks={}\n", job.arrayJobId, job.mergeJobId, job.tasks.size());
    for (size_t i = 0; i < job.tasks.size(); ++i) text += fmt::format("task.{}={}\n", i, fmt::join(job.tasks[i], " "));
    return text;
}

FarmJob readJobFile(const fs::path &folder) {
    const fs::path file = jobFilePath(folder);
    std::ifstream in(file);
    if (!in) throw InputError(FileLoc{folder.string()}, "no veduta farm job here (farm.job is missing)");
    std::map<std::string, std::string> values;
    for (std::string line; std::getline(in, line);) {
        size_t equals = line.find('=');
        if (!line.starts_with('#') && equals != std::string::npos)
            values[line.substr(0, equals)] = line.substr(equals + 1);
    }
    FarmJob job;
    job.folder = fs::absolute(folder);
    job.name = required(values, "name", file);
    job.program = required(values, "program", file);
    job.scene = required(values, "scene", file);
    job.output = required(values, "output", file);
    job.arrayJobId = required(values, "array_job", file);
    job.mergeJobId = required(values, "merge_job", file);
    const std::string &count = required(values, "tasks", file);
    if (count.empty() || count.find_first_not_of("0123456789") != std::string::npos || count.size() > 9) {
        throw InputError(FileLoc{file.string()}, fmt::format("not a veduta farm job file: tasks={}", count));
    }
    for (size_t i = 0; i < std::stoul(count); ++i)
        job.tasks.push_back(words(required(values, fmt::format("task.{}", i), file)));
    return job;
}

}  // namespace veduta
