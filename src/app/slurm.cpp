#include "app/slurm.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

extern char **environ;

namespace veduta {

namespace fs = std::filesystem;

namespace {

struct Pipe {
    int read = -1, write = -1;
    Pipe() {
        int fds[2];
        if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
        read = fds[0], write = fds[1];
    }
    ~Pipe() { closeBoth(); }
    Pipe(const Pipe &) = delete;
    Pipe &operator=(const Pipe &) = delete;
    void closeWrite() { closeEnd(write); }
    void closeBoth() { closeEnd(read), closeEnd(write); }
    static void closeEnd(int &fd) {
        if (fd >= 0) close(fd);
        fd = -1;
    }
};

// Reads both pipes to their ends together, so that neither fills while the other is waited on.
void drain(Pipe &out, Pipe &err, ProgramResult &result) {
    std::array<pollfd, 2> fds{pollfd{out.read, POLLIN, 0}, pollfd{err.read, POLLIN, 0}};
    std::array<std::string *, 2> texts{&result.out, &result.err};
    int open = 2;
    while (open > 0) {
        if (poll(fds.data(), fds.size(), -1) < 0) {
            if (errno == EINTR) continue;
            throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
        }
        for (size_t i = 0; i < fds.size(); ++i) {
            if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            char buffer[4096];
            ssize_t n = ::read(fds[i].fd, buffer, sizeof buffer);
            if (n > 0) {
                texts[i]->append(buffer, size_t(n));
            } else if (n == 0 || errno != EINTR) {
                fds[i].fd = -1;
                --open;
            }
        }
    }
}

int waitFor(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string trimmed(const std::string &text) {
    size_t end = text.find_last_not_of(" \t\r\n");
    return end == std::string::npos ? "" : text.substr(0, end + 1);
}

// The program's own message, or its exit status where it printed none.
std::string failureOf(const std::string &program, const ProgramResult &r) {
    std::string message = trimmed(r.err);
    return fmt::format("{} failed{}", program,
                       message.empty() ? fmt::format(" with exit status {}", r.status) : fmt::format(": {}", message));
}

}  // namespace

std::optional<fs::path> findOnPath(const std::string &name) {
    const char *path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    for (std::string folder; std::getline(folders, folder, ':');) {
        fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
        if (access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate;
    }
    return std::nullopt;
}

ProgramResult runProgram(const std::vector<std::string> &argv) {
    Pipe out, err;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, out.write, STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, err.write, STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, out.read);
    posix_spawn_file_actions_addclose(&actions, err.read);
    std::vector<char *> args;
    for (const std::string &arg : argv) args.push_back(const_cast<char *>(arg.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    int error = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw std::runtime_error(fmt::format("cannot run {}: {}", argv[0], std::strerror(error)));
    out.closeWrite();
    err.closeWrite();
    ProgramResult result;
    drain(out, err, result);
    result.status = waitFor(pid);
    return result;
}

std::string submitBatchJob(const fs::path &script, const std::vector<std::string> &options) {
    std::vector<std::string> argv{"sbatch", "--parsable"};
    argv.insert(argv.end(), options.begin(), options.end());
    argv.push_back(script.string());
    ProgramResult r = runProgram(argv);
    // --parsable prints "ID" or "ID;CLUSTER".
    std::string id = trimmed(r.out).substr(0, trimmed(r.out).find(';'));
    if (r.status != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos) {
        throw std::runtime_error(fmt::format("{} ({})", failureOf("sbatch", r), script.string()));
    }
    return id;
}

void cancelJob(const std::string &id) {
    ProgramResult r = runProgram({"scancel", id});
    if (r.status != 0)
        std::fprintf(stderr, "veduta: warning: %s\n", failureOf(fmt::format("scancel {}", id), r).c_str());
}

std::vector<QueuedJob> queuedJobs(const std::vector<std::string> &names) {
    ProgramResult r = runProgram({"squeue", "--noheader", "--array", "--states=all",
                                  fmt::format("--name={}", fmt::join(names, ",")), "--format=%j|%K|%T|%r"});
    if (r.status != 0) throw std::runtime_error(failureOf("squeue", r));
    std::vector<QueuedJob> jobs;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> fields;
        std::istringstream parts(trimmed(line));
        for (std::string field; std::getline(parts, field, '|');) fields.push_back(field);
        if (fields.size() != 4) continue;
        bool inArray = !fields[1].empty() && fields[1].find_first_not_of("0123456789") == std::string::npos;
        jobs.push_back({fields[0], inArray ? std::atoi(fields[1].c_str()) : -1, fields[2], fields[3]});
    }
    return jobs;
}

bool isLiveState(const std::string &state) {
    static const std::set<std::string> live{"PENDING",     "RUNNING",      "CONFIGURING",  "COMPLETING", "REQUEUED",
                                            "REQUEUE_FED", "REQUEUE_HOLD", "RESIZING",     "SUSPENDED",  "SIGNALING",
                                            "STAGE_OUT",   "STOPPED",      "RESV_DEL_HOLD"};
    return live.contains(state);
}

}  // namespace veduta
