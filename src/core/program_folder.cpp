#include "core/program_folder.h"

namespace veduta {

namespace fs = std::filesystem;

std::optional<fs::path> runningProgram() {
    std::error_code error;
    fs::path self = fs::read_symlink("/proc/self/exe", error);
    if (error) return std::nullopt;
    return self;
}

std::optional<fs::path> runningProgramFolder() {
    std::optional<fs::path> self = runningProgram();
    if (!self) return std::nullopt;
    return self->parent_path();
}

namespace {

// The build tree's folders: the program's and, for data, each one above it up to the root.
std::vector<fs::path> buildTreeFolders(ProgramPart part, const fs::path &programFolder) {
    if (part == ProgramPart::Helper) return {programFolder};
    std::vector<fs::path> folders;
    for (fs::path dir = programFolder; !dir.empty(); dir = dir.parent_path()) {
        folders.push_back(dir);
        if (dir == dir.parent_path()) break;
    }
    return folders;
}

}  // namespace

std::vector<fs::path> programPartFolders(ProgramPart part, const fs::path &programFolder) {
    // The installed layout, bin/ beside lib/veduta/ and share/veduta/ (cmake/VedutaInstall.cmake).
    fs::path installed =
        (programFolder / (part == ProgramPart::Helper ? "../lib/veduta" : "../share/veduta")).lexically_normal();
    std::vector<fs::path> folders = buildTreeFolders(part, programFolder);
    // Helpers beside the program come first, as they always have; data installed comes first,
    // so that an installed veduta never picks up a stray rules/ above /usr/bin.
    folders.insert(part == ProgramPart::Helper ? folders.end() : folders.begin(), installed);
    return folders;
}

std::optional<fs::path> findProgramPart(ProgramPart part, const fs::path &relative) {
    std::optional<fs::path> programFolder = runningProgramFolder();
    if (!programFolder) return std::nullopt;
    for (const fs::path &folder : programPartFolders(part, *programFolder)) {
        std::error_code error;
        if (fs::exists(folder / relative, error)) return folder / relative;
    }
    return std::nullopt;
}

std::string programPartFolderList(ProgramPart part) {
    std::optional<fs::path> programFolder = runningProgramFolder();
    if (!programFolder) return "nowhere: the program's own folder is unknown without /proc/self/exe";
    std::string list;
    for (const fs::path &folder : programPartFolders(part, *programFolder))
        list += (list.empty() ? "" : ", ") + folder.string();
    return list;
}

}  // namespace veduta
