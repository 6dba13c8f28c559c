#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "app/commands.h"
#include "core/program_folder.h"

namespace veduta {

namespace {

constexpr const char *kDiffProgram = "veduta-diff";

// veduta-diff is built beside veduta and installed in ../lib/veduta (ProgramPart::Helper).
// Where /proc is missing, the folder argv[0] names serves; a bare name means veduta was found
// on PATH, and so is veduta-diff.
std::string diffProgram(const char *argv0) {
    if (auto found = findProgramPart(ProgramPart::Helper, kDiffProgram)) return found->string();
    if (auto folder = runningProgramFolder()) return (*folder / kDiffProgram).string();
    std::filesystem::path invoked(argv0);
    return invoked.has_parent_path() ? (invoked.parent_path() / kDiffProgram).string() : kDiffProgram;
}

}  // namespace

int runDiffProgram(int argc, char **argv) {
    std::string program = diffProgram(argv[0]);
    std::vector<char *> args(argv, argv + argc);
    args[0] = program.data();
    args.push_back(nullptr);
    execvp(program.c_str(), args.data());  // searches PATH only for a bare name
    std::fprintf(stderr, "veduta: error: cannot run %s: %s (veduta looks for %s in %s)\n", program.c_str(),
                 std::strerror(errno), kDiffProgram, programPartFolderList(ProgramPart::Helper).c_str());
    return 2;  // veduta diff's exit code for an error
}

}  // namespace veduta
