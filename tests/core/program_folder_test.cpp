#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/program_folder.h"

namespace veduta {
namespace {

using Folders = std::vector<std::filesystem::path>;

TEST(ProgramFolder, HelpersBesideTheProgramThenInLibVeduta) {
    EXPECT_EQ(programPartFolders(ProgramPart::Helper, "/opt/v/bin"), (Folders{"/opt/v/bin", "/opt/v/lib/veduta"}));
}

TEST(ProgramFolder, DataInstalledFirstThenUpwards) {
    EXPECT_EQ(programPartFolders(ProgramPart::Data, "/opt/v/bin"),
              (Folders{"/opt/v/share/veduta", "/opt/v/bin", "/opt/v", "/opt", "/"}));
}

TEST(ProgramFolder, InstalledFoldersOfAProgramAtTheRoot) {
    EXPECT_EQ(programPartFolders(ProgramPart::Helper, "/bin"), (Folders{"/bin", "/lib/veduta"}));
    EXPECT_EQ(programPartFolders(ProgramPart::Data, "/bin"), (Folders{"/share/veduta", "/bin", "/"}));
}

TEST(ProgramFolder, ListNamesTheRunningProgramsFolders) {
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe").parent_path();
    std::string list = programPartFolderList(ProgramPart::Helper);
    EXPECT_EQ(list, self.string() + ", " + (self / "../lib/veduta").lexically_normal().string());
}

TEST(ProgramFolder, FindsOnlyWhatExists) {
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe");
    EXPECT_EQ(findProgramPart(ProgramPart::Helper, self.filename()), self);
    EXPECT_EQ(findProgramPart(ProgramPart::Helper, "no-such-part"), std::nullopt);
}

}  // namespace
}  // namespace veduta
