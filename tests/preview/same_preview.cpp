#include "same_preview.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

namespace veduta::test {

void expectSameForAnyThreadsAndTiles(const RenderScene &scene, std::initializer_list<PreviewMode> modes) {
    for (PreviewMode mode : modes) {
        PreviewOptions options;
        options.mode = mode;
        options.wireframe = options.shadows = true;
        auto draw = [&](int threads, int tileSize) {
            options.tileSize = tileSize;
            return tbb::task_arena(threads).execute([&] { return renderPreview(scene, options); });
        };
        PreviewImage reference = draw(1, 64);
        for (int tileSize : {1, 7, 4096}) {
            PreviewImage other = draw(2, tileSize);
            EXPECT_EQ(reference.film.pixels(), other.film.pixels()) << "mode " << int(mode) << " tile " << tileSize;
            EXPECT_EQ(reference.depth, other.depth) << "mode " << int(mode) << " tile " << tileSize;
            EXPECT_EQ(reference.objectId, other.objectId) << "mode " << int(mode) << " tile " << tileSize;
        }
    }
}

}  // namespace veduta::test
