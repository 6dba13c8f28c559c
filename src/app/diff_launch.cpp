#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include <unistd.h>

#include "app/commands.h"

namespace veduta {

namespace {

// veduta-diff is installed and built beside the veduta program itself.
std::filesystem::path diffProgram() {
    std::error_code error;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    return (error ? std::filesystem::path("veduta") : self).parent_path() / "veduta-diff";
}

}  // namespace

int runDiffProgram(int argc, char **argv) {
    std::filesystem::path program = diffProgram();
    std::vector<char *> args(argv, argv + argc);
    std::string name = program.string();
    args[0] = name.data();
    args.push_back(nullptr);
    execv(name.c_str(), args.data());
    std::fprintf(stderr, "veduta: error: cannot run %s: %s\n", name.c_str(), std::strerror(errno));
    return kExitFailure;
}

}  // namespace veduta
