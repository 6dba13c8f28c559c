#include "app/shipped_files.h"

#include <optional>

#include <fmt/format.h>

#include "core/error.h"
#include "core/program_folder.h"

namespace veduta {

std::filesystem::path shippedFile(const std::filesystem::path &relative, const std::string &option) {
    if (std::optional<std::filesystem::path> file = findProgramPart(ProgramPart::Data, relative)) return *file;
    throw InputError(FileLoc{option},
                     fmt::format("{} was not found in {}; name a file", relative.generic_string(),
                                 programPartFolderList(ProgramPart::Data)));
}

std::filesystem::path shippedBuildingRules(const std::string &option) {
    return shippedFile("rules/gruenderzeit/FacadeStructure.xml", option);
}

std::filesystem::path shippedUrbanGeography(const std::string &option) {
    return shippedFile("rules/slg/urban-geography.xml", option);
}

}  // namespace veduta
