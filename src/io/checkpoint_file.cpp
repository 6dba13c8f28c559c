#include "io/checkpoint_file.h"

#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "core/error.h"
#include "io/atomic_file.h"

namespace veduta {

namespace {

constexpr const char *kMagic = "veduta checkpoint 1";

template <typename T>
void put(std::string &out, const T &value) {
    out.append(reinterpret_cast<const char *>(&value), sizeof(T));
}

void putStats(std::string &out, const RenderStats &s) {
    put(out, s.samplesDone);
    put(out, s.seconds);
    put(out, s.rays.camera);
    put(out, s.rays.bounce);
    put(out, s.rays.shadow);
    put(out, s.nonFiniteSamples);
}

class Reader {
  public:
    Reader(const std::filesystem::path &file, std::string bytes) : file_(file), bytes_(std::move(bytes)) {}

    std::string line() {
        size_t end = bytes_.find('\n', at_);
        if (end == std::string::npos) fail("ends inside its header");
        std::string text = bytes_.substr(at_, end - at_);
        at_ = end + 1;
        return text;
    }
    void raw(void *out, size_t size) {
        if (bytes_.size() - at_ < size) fail("is cut short");
        std::memcpy(out, bytes_.data() + at_, size);
        at_ += size;
    }
    template <typename T>
    T get() {
        T value;
        raw(&value, sizeof(T));
        return value;
    }
    bool atEnd() const { return at_ == bytes_.size(); }
    [[noreturn]] void fail(const std::string &what) const {
        throw InputError(FileLoc{file_.string()}, fmt::format("the checkpoint {}", what));
    }

  private:
    std::filesystem::path file_;
    std::string bytes_;
    size_t at_ = 0;
};

std::string readWhole(const std::filesystem::path &file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(FileLoc{file.string()}, "cannot read the checkpoint");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

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
    std::string out = fmt::format("{}\n", kMagic);
    for (const auto &[key, value] : identity) out += fmt::format("{}: {}\n", key, value);
    out += "\n";
    putStats(out, stats);
    for (const FilmBuffer &buffer : film.buffers()) {
        put(out, uint64_t(buffer.bytes.size()));
        out.append(reinterpret_cast<const char *>(buffer.bytes.data()), buffer.bytes.size());
    }
    writeBytesAtomically(file, out.data(), out.size());
}

void readCheckpoint(const std::filesystem::path &file, const RenderIdentity &identity, Film &film,
                    RenderStats &stats) {
    Reader reader(file, readWhole(file));
    if (reader.line() != kMagic) reader.fail("does not start with its signature: not a veduta checkpoint");
    RenderIdentity written;
    for (std::string text = reader.line(); !text.empty(); text = reader.line()) {
        size_t colon = text.find(": ");
        if (colon == std::string::npos) reader.fail(fmt::format("has a damaged header line '{}'", text));
        written.emplace_back(text.substr(0, colon), text.substr(colon + 2));
    }
    checkIdentity(reader, written, identity);
    stats.samplesDone = reader.get<uint32_t>();
    stats.seconds = reader.get<double>();
    stats.rays.camera = reader.get<uint64_t>();
    stats.rays.bounce = reader.get<uint64_t>();
    stats.rays.shadow = reader.get<uint64_t>();
    stats.nonFiniteSamples = reader.get<uint64_t>();
    for (const FilmBuffer &buffer : film.buffers()) {
        if (reader.get<uint64_t>() != buffer.bytes.size()) {
            reader.fail(fmt::format("has a {} buffer of the wrong size", buffer.name));
        }
        reader.raw(buffer.bytes.data(), buffer.bytes.size());
    }
    if (!reader.atEnd()) reader.fail("has data after its last buffer");
}

}  // namespace veduta
