// Checkpoints refuse what they cannot trust: any one changed byte, a cut file, another format.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.h"
#include "film/film.h"
#include "io/checkpoint_file.h"
#include "render/renderer.h"
#include "test_scenes.h"

namespace veduta {
namespace {

class CheckpointFile : public testing::Test {
  protected:
    void SetUp() override {
        scene_ = test::sceneFromXml(R"(<scene version="1">
  <camera position="0 -10 1" look_at="0 0 1" fov="40" resolution="3 2"/>
  <render spp="2"/>
  <box size="2 2 2"/>
</scene>)");
        Bvh bvh(scene_);
        RenderStats stats;
        Film film = render(scene_, bvh, {}, &stats);
        writeCheckpoint(file_, identity_, film, stats);
        std::ifstream in(file_, std::ios::binary);
        bytes_.assign(std::istreambuf_iterator<char>(in), {});
    }

    // The message readCheckpoint gives for a file of `bytes`, or "no error".
    std::string errorFor(const std::string &bytes) {
        std::ofstream(file_, std::ios::binary | std::ios::trunc) << bytes;
        Film film = makeFilm(scene_, {});
        RenderStats stats;
        try {
            readCheckpoint(file_, identity_, film, stats);
        } catch (const InputError &e) {
            return e.what();
        }
        return "no error";
    }

    RenderScene scene_;
    RenderIdentity identity_{{"scene", "abc"}, {"samples", "2"}};
    test::ScratchFolder folder_{"checkpoint_file"};
    std::filesystem::path file_ = folder_.path() / "c.checkpoint";
    std::string bytes_;
};

TEST_F(CheckpointFile, AWholeFileIsRead) { EXPECT_EQ(errorFor(bytes_), "no error"); }

TEST_F(CheckpointFile, AnyOneChangedByteIsRefused) {
    ASSERT_GT(bytes_.size(), 100u);
    for (size_t at = 0; at < bytes_.size(); ++at) {
        for (char flip : {'\x01', '\x80', '\xff'}) {
            std::string damaged = bytes_;
            damaged[at] = char(damaged[at] ^ flip);
            std::string error = errorFor(damaged);
            ASSERT_NE(error, "no error") << "byte " << at << " of " << bytes_.size() << " xor " << int(flip);
            ASSERT_EQ(error.rfind(file_.string() + ": the checkpoint ", 0), 0u) << error;
        }
    }
}

TEST_F(CheckpointFile, ADamagedBufferSaysSo) {
    std::string damaged = bytes_;
    damaged[damaged.size() - 10] ^= 0x10;
    EXPECT_EQ(errorFor(damaged),
              file_.string() + ": the checkpoint is damaged: its CRC-32 does not match its contents");
}

TEST_F(CheckpointFile, CutFilesAndOtherFormatsAreRefused) {
    for (size_t keep : {size_t(0), size_t(10), bytes_.size() / 2, bytes_.size() - 1})
        EXPECT_NE(errorFor(bytes_.substr(0, keep)), "no error") << keep;
    EXPECT_EQ(errorFor(bytes_ + "x"), file_.string() + ": the checkpoint has data after its last buffer");
    std::string older = bytes_;
    older.replace(0, std::string("veduta checkpoint 2").size(), "veduta checkpoint 1");
    EXPECT_EQ(errorFor(older),
              file_.string() +
                  ": the checkpoint is of another format ('veduta checkpoint 1'); render afresh without "
                  "--resume");
}

}  // namespace
}  // namespace veduta
