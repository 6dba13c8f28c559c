#include "app/shipped_files.h"

#include <optional>

#include <fmt/format.h>

#include "core/error.h"
#include "core/program_folder.h"

namespace veduta {

std::filesystem::path shippedFile(const std::filesystem::path &relative, const std::string &option) {
    if (std::optional<std::filesystem::path> folder = runningProgramFolder())
        for (std::filesystem::path dir = *folder; !dir.empty(); dir = dir.parent_path()) {
            if (std::filesystem::is_regular_file(dir / relative)) return dir / relative;
            if (dir == dir.parent_path()) break;
        }
    throw InputError(FileLoc{option},
                     fmt::format("{} was not found beside the program; name a file", relative.generic_string()));
}

std::filesystem::path shippedBuildingRules(const std::string &option) {
    return shippedFile("rules/gruenderzeit/FacadeStructure.xml", option);
}

std::filesystem::path shippedUrbanGeography(const std::string &option) {
    return shippedFile("rules/slg/urban-geography.xml", option);
}

}  // namespace veduta
