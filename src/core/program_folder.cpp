#include "core/program_folder.h"

namespace veduta {

std::optional<std::filesystem::path> runningProgramFolder() {
    std::error_code error;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) return std::nullopt;
    return self.parent_path();
}

}  // namespace veduta
