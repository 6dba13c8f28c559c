#include "io/checkpoint_file.h"

#include <cstring>
#include <fstream>
#include <map>
#include <span>
#include <string_view>

#include <fmt/format.h>
#include <zlib.h>

#include "core/atomic_file.h"
#include "core/error.h"

namespace veduta {

namespace {

// Format 2 ends in a CRC-32 of everything before it, so that a damaged file is refused
// rather than resumed into a wrong image.
constexpr std::string_view kMagic = "veduta checkpoint 2";
constexpr std::string_view kAnyFormat = "veduta checkpoint ";

uint32_t crcOf(uint32_t crc, std::span<const std::byte> bytes) {
    return uint32_t(crc32_z(crc, reinterpret_cast<const Bytef *>(bytes.data()), bytes.size()));
}

// RenderStats as the file stores them, in this order.
struct StoredStats {
    uint64_t samplesDone;
    double seconds;
    uint64_t camera, bounce, shadow, nonFinite;
};

// Reads the checkpoint straight into the film's buffers (a film may be gigabytes, too much to
// hold twice) and sums the CRC of what it has read.
class Reader {
  public:
    explicit Reader(const std::filesystem::path &file) : file_(file), in_(file, std::ios::binary) {
        if (!in_) throw InputError(FileLoc{file.string()}, "cannot read the checkpoint");
    }

    std::string line() {
        std::string text;
        if (!std::getline(in_, text)) fail("ends inside its header");
        crc_ = crcOf(crc_, std::as_bytes(std::span(text)));
        crc_ = crcOf(crc_, std::as_bytes(std::span("\n", 1)));
        return text;
    }
    void raw(void *out, size_t size) {
        if (!in_.read(static_cast<char *>(out), std::streamsize(size))) fail("is cut short");
        crc_ = crcOf(crc_, {static_cast<const std::byte *>(out), size});
    }
    // The CRC the file ends with against that of everything read before it.
    void checkCrc() {
        uint32_t summed = crc_, stored = get<uint32_t>();
        if (stored != summed) fail("is damaged: its CRC-32 does not match its contents");
    }
    template <typename T>
    T get() {
        T value;
        raw(&value, sizeof(T));
        return value;
    }
    bool atEnd() { return in_.peek() == std::char_traits<char>::eof(); }
    [[noreturn]] void fail(const std::string &what) const {
        throw InputError(FileLoc{file_.string()}, fmt::format("the checkpoint {}", what));
    }

  private:
    std::filesystem::path file_;
    std::ifstream in_;
    uint32_t crc_ = 0;
};

void checkIdentity(const Reader &reader, const RenderIdentity &written, const RenderIdentity &expected) {
    std::map<std::string, std::string> there(written.begin(), written.end());
    std::string differences;
    for (const auto &[key, value] : expected) {
        auto it = there.find(key);
        std::string old = it == there.end() ? "(missing)" : it->second;
        if (old != value) differences += fmt::format("\n  {}: {} there, {} here", key, old, value);
    }
    if (!differences.empty()) reader.fail(fmt::format("was written for a different render:{}", differences));
}

}  // namespace

void writeCheckpoint(const std::filesystem::path &file, const RenderIdentity &identity, Film &film,
                     const RenderStats &stats) {
    std::string header = fmt::format("{}\n", kMagic);
    for (const auto &[key, value] : identity) header += fmt::format("{}: {}\n", key, value);
    header += "\n";
    const StoredStats stored{stats.samplesDone, stats.seconds,     stats.rays.camera,
                             stats.rays.bounce, stats.rays.shadow, stats.nonFiniteSamples};
    std::vector<FilmBuffer> buffers = film.buffers();
    std::vector<uint64_t> sizes;
    for (const FilmBuffer &buffer : buffers) sizes.push_back(buffer.bytes.size());
    std::vector<std::span<const std::byte>> pieces{std::as_bytes(std::span(header)),
                                                   std::as_bytes(std::span(&stored, 1))};
    for (size_t i = 0; i < buffers.size(); ++i) {
        pieces.push_back(std::as_bytes(std::span(&sizes[i], 1)));
        pieces.push_back(buffers[i].bytes);
    }
    uint32_t crc = 0;
    for (std::span<const std::byte> piece : pieces) crc = crcOf(crc, piece);
    pieces.push_back(std::as_bytes(std::span(&crc, 1)));
    writeBytesAtomically(file, pieces);
}

void readCheckpoint(const std::filesystem::path &file, const RenderIdentity &identity, Film &film, RenderStats &stats) {
    Reader reader(file);
    std::string signature = reader.line();
    if (signature != kMagic) {
        if (signature.starts_with(kAnyFormat))
            reader.fail(fmt::format("is of another format ('{}'); render afresh without --resume", signature));
        reader.fail("does not start with its signature: not a veduta checkpoint");
    }
    RenderIdentity written;
    for (std::string text = reader.line(); !text.empty(); text = reader.line()) {
        size_t colon = text.find(": ");
        if (colon == std::string::npos) reader.fail(fmt::format("has a damaged header line '{}'", text));
        written.emplace_back(text.substr(0, colon), text.substr(colon + 2));
    }
    checkIdentity(reader, written, identity);
    StoredStats stored = reader.get<StoredStats>();
    stats.samplesDone = uint32_t(stored.samplesDone);
    stats.seconds = stored.seconds;
    stats.rays = {stored.camera, stored.bounce, stored.shadow};
    stats.nonFiniteSamples = stored.nonFinite;
    for (const FilmBuffer &buffer : film.buffers()) {
        if (reader.get<uint64_t>() != buffer.bytes.size()) {
            reader.fail(fmt::format("has a {} buffer of the wrong size", buffer.name));
        }
        reader.raw(buffer.bytes.data(), buffer.bytes.size());
    }
    reader.checkCrc();
    if (!reader.atEnd()) reader.fail("has data after its last buffer");
}

}  // namespace veduta
