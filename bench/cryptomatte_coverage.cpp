// The mean Cryptomatte coverage of one object or material over a veduta EXR, as veduta stored
// it: what Blender's Cryptomatte node must give as the mean of its matte for that name
// (bench/blender_cryptomatte.sh).
// Usage: bench_cryptomatte_coverage FILE.exr object|material NAME
#include <bit>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "film/cryptomatte.h"
#include "io/exr_file.h"

int main(int argc, char **argv) {
    using namespace veduta;
    if (argc != 4 || (std::strcmp(argv[2], "object") != 0 && std::strcmp(argv[2], "material") != 0)) {
        std::fprintf(stderr, "usage: %s FILE.exr object|material NAME\n", argv[0]);
        return 2;
    }
    try {
        const LayeredImage image = readExr(argv[1]);
        CryptomatteKind kind = argv[2][0] == 'o' ? CryptomatteKind::Object : CryptomatteKind::Material;
        if (storedRanks(image, kind) == 0) {
            std::fprintf(stderr, "%s has no %s layers\n", argv[1], cryptomattePass(kind));
            return 1;
        }
        std::vector<const std::vector<float> *> channels = rankChannels(image, kind);
        uint32_t id = cryptomatteIdBits(argv[3]);
        size_t pixels = image.dataWindow.width() * size_t(image.dataWindow.height());
        double sum = 0;
        for (size_t p = 0; p < pixels; ++p) {
            for (size_t rank = 0; 2 * rank < channels.size(); ++rank) {
                if (std::bit_cast<uint32_t>((*channels[2 * rank])[p]) == id) sum += (*channels[2 * rank + 1])[p];
            }
        }
        std::printf("%.6f\n", sum / double(pixels));
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
