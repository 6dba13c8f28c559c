// Outputs written together change together: a failure part-way puts every older file back and
// leaves no new one; a committed set keeps the new files and drops the older ones.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "core/atomic_file.h"
#include "test_scenes.h"

namespace veduta {
namespace {

std::string contents(const std::filesystem::path &file) {
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void put(const std::filesystem::path &file, const std::string &text) {
    writeBytesAtomically(file, text.data(), text.size());
}

class OutputSetTest : public testing::Test {
  protected:
    test::ScratchFolder folder_{"output_set"};
    std::filesystem::path exr_ = folder_.path() / "x.exr", png_ = folder_.path() / "x.png",
                          face_ = folder_.path() / "x_nz.exr";

    size_t filesInFolder() const {
        return size_t(std::distance(std::filesystem::directory_iterator(folder_.path()), {}));
    }
};

TEST_F(OutputSetTest, AFailurePartWayLeavesTheFolderAsItWas) {
    put(exr_, "older image");
    try {
        OutputSet outputs({exr_, png_, ""});
        put(exr_, "newer image");
        put(png_, "newer png");
        throw std::runtime_error("the third output failed");
    } catch (const std::runtime_error &) {}
    EXPECT_EQ(contents(exr_), "older image");
    EXPECT_FALSE(std::filesystem::exists(png_));
    EXPECT_EQ(filesInFolder(), 1u) << "no backup or temporary is left";
}

// The first write fails: the older file was never replaced, and its backup (a second link to
// it) must go too.
TEST_F(OutputSetTest, AFailureBeforeTheFirstWriteLeavesNoBackup) {
    put(exr_, "older image");
    try {
        OutputSet outputs({exr_, png_});
        throw std::runtime_error("the first output failed");
    } catch (const std::runtime_error &) {}
    EXPECT_EQ(contents(exr_), "older image");
    EXPECT_EQ(filesInFolder(), 1u);
}

TEST_F(OutputSetTest, ACommittedSetKeepsTheNewFiles) {
    put(exr_, "older image");
    {
        OutputSet outputs({exr_, png_, face_});
        put(exr_, "newer image");
        put(png_, "newer png");
        put(face_, "face");
        outputs.commit();
    }
    EXPECT_EQ(contents(exr_), "newer image");
    EXPECT_EQ(contents(png_), "newer png");
    EXPECT_EQ(contents(face_), "face");
    EXPECT_EQ(filesInFolder(), 3u);
}

}  // namespace
}  // namespace veduta
