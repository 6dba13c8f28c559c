// Where the running program lives, and where it looks for its parts: the veduta-diff program
// and the image plugin (as git finds git-foo), and the files it ships (rules/, …). One list of
// places, so that the lookup and its error messages agree, for the build tree and for an
// installation (docs/install.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace veduta {

// The running executable, whatever name or link started it, from /proc/self/exe; nothing where
// /proc is missing.
std::optional<std::filesystem::path> runningProgram();
// Its folder.
std::optional<std::filesystem::path> runningProgramFolder();

enum class ProgramPart {
    Helper,  // veduta-diff and veduta-images.so: beside the program (build tree), ../lib/veduta
    Data,    // rules/, …: ../share/veduta, then the program's folder and each one above it (source tree)
};

// The folders `part` is looked for in, first first, for a program in `programFolder`.
std::vector<std::filesystem::path> programPartFolders(ProgramPart part, const std::filesystem::path &programFolder);

// `relative` in the first of the running program's folders for `part` that holds it.
std::optional<std::filesystem::path> findProgramPart(ProgramPart part, const std::filesystem::path &relative);

// The running program's folders for `part`, for an error message: "a, b, c", or a note that
// the program's own folder is unknown.
std::string programPartFolderList(ProgramPart part);

}  // namespace veduta
