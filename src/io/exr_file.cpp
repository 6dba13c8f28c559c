#include "io/exr_file.h"

#include <cstring>
#include <stdexcept>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>

#include "core/atomic_file.h"

namespace veduta {

namespace {

// OpenEXR's own file stream flushes its last buffer when it is destroyed, where a full disk
// goes unnoticed; encoding into memory leaves the writing to writeWholeFile, which checks it.
class MemoryStream final : public Imf::OStream {
  public:
    MemoryStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (position_ + size_t(n) > bytes_.size()) bytes_.resize(position_ + size_t(n));
        std::memcpy(bytes_.data() + position_, c, size_t(n));
        position_ += size_t(n);
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = position; }
    const std::vector<char> &bytes() const { return bytes_; }

  private:
    std::vector<char> bytes_;
    size_t position_ = 0;
};

struct Codec {
    ExrCompression compression;
    const char *name;
    Imf::Compression openexr;
};

const Codec kCodecs[] = {
    {ExrCompression::None, "none", Imf::NO_COMPRESSION},   {ExrCompression::Rle, "rle", Imf::RLE_COMPRESSION},
    {ExrCompression::Zips, "zips", Imf::ZIPS_COMPRESSION}, {ExrCompression::Zip, "zip", Imf::ZIP_COMPRESSION},
    {ExrCompression::Piz, "piz", Imf::PIZ_COMPRESSION},    {ExrCompression::Pxr24, "pxr24", Imf::PXR24_COMPRESSION},
    {ExrCompression::B44, "b44", Imf::B44_COMPRESSION},    {ExrCompression::B44a, "b44a", Imf::B44A_COMPRESSION},
    {ExrCompression::Dwaa, "dwaa", Imf::DWAA_COMPRESSION}, {ExrCompression::Dwab, "dwab", Imf::DWAB_COMPRESSION}};

const Codec &codecOf(ExrCompression compression) {
    for (const Codec &codec : kCodecs) {
        if (codec.compression == compression) return codec;
    }
    throw std::logic_error("an EXR compression without a codec");
}

ExrCompression compressionOf(Imf::Compression openexr) {
    for (const Codec &codec : kCodecs) {
        if (codec.openexr == openexr) return codec.compression;
    }
    throw std::runtime_error("the file's compression is not one veduta writes");
}

// ITU-R BT.709 primaries and D65 white: the colour space of every veduta render.
Imf::Chromaticities rec709() {
    return Imf::Chromaticities({0.64f, 0.33f}, {0.30f, 0.60f}, {0.15f, 0.06f}, {0.3127f, 0.3290f});
}

Imath::Box2i toBox(const PixelWindow &w) { return Imath::Box2i({w.x0, w.y0}, {w.x1 - 1, w.y1 - 1}); }
PixelWindow toWindow(const Imath::Box2i &b) { return {b.min.x, b.min.y, b.max.x + 1, b.max.y + 1}; }

void insertMetadata(Imf::Header &header, const std::string &name, const MetadataValue &value) {
    if (auto *s = std::get_if<std::string>(&value)) header.insert(name, Imf::StringAttribute(*s));
    if (auto *i = std::get_if<int>(&value)) header.insert(name, Imf::IntAttribute(*i));
    if (auto *d = std::get_if<double>(&value)) header.insert(name, Imf::DoubleAttribute(*d));
    if (auto *m = std::get_if<Matrix44>(&value)) {
        Imath::M44f matrix;
        std::memcpy(&matrix[0][0], m->data(), sizeof(float) * 16);
        header.insert(name, Imf::M44fAttribute(matrix));
    }
}

void readMetadata(const Imf::Header &header, LayeredImage &image) {
    // The attributes every header has (windows, pixelAspectRatio, …) are not metadata: the
    // writer's header sets them, and it would refuse pixelAspectRatio back as a double.
    const Imf::Header required;
    for (auto a = header.begin(); a != header.end(); ++a) {
        if (required.find(a.name()) != required.end()) continue;
        const Imf::Attribute &attribute = a.attribute();
        if (auto *s = dynamic_cast<const Imf::StringAttribute *>(&attribute)) image.metadata[a.name()] = s->value();
        if (auto *i = dynamic_cast<const Imf::IntAttribute *>(&attribute)) image.metadata[a.name()] = i->value();
        if (auto *f = dynamic_cast<const Imf::FloatAttribute *>(&attribute)) {
            image.metadata[a.name()] = double(f->value());
        }
        if (auto *d = dynamic_cast<const Imf::DoubleAttribute *>(&attribute)) image.metadata[a.name()] = d->value();
        if (auto *m = dynamic_cast<const Imf::M44fAttribute *>(&attribute)) {
            Matrix44 matrix;
            std::memcpy(matrix.data(), &m->value()[0][0], sizeof(float) * 16);
            image.metadata[a.name()] = matrix;
        }
    }
}

// OpenEXR's slices address pixel (x, y) as base + x·xStride + y·yStride, for absolute x and y.
template <typename T>
char *sliceBase(const std::vector<T> &values, const PixelWindow &w) {
    auto *origin = reinterpret_cast<char *>(const_cast<T *>(values.data()));
    return origin - (ptrdiff_t(w.x0) + ptrdiff_t(w.y0) * w.width()) * ptrdiff_t(sizeof(T));
}

}  // namespace

const std::vector<std::string> &exrCompressionNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (const Codec &codec : kCodecs) all.emplace_back(codec.name);
        return all;
    }();
    return names;
}

std::string_view exrCompressionName(ExrCompression compression) { return codecOf(compression).name; }

std::optional<ExrCompression> exrCompressionNamed(std::string_view name) {
    for (const Codec &codec : kCodecs) {
        if (name == codec.name) return codec.compression;
    }
    return std::nullopt;
}

bool changesFloatChannels(ExrCompression compression) {
    return compression == ExrCompression::Pxr24 || compression == ExrCompression::Dwaa ||
        compression == ExrCompression::Dwab;
}

void writeExr(const LayeredImage &image, const std::filesystem::path &file, const ExrFormat &format) {
    const PixelWindow &w = image.dataWindow;
    MemoryStream stream;
    try {
        Imf::Header header(toBox({0, 0, image.fullWidth, image.fullHeight}), toBox(w));
        header.compression() = codecOf(format.compression).openexr;
        for (const auto &[name, value] : image.metadata) insertMetadata(header, name, value);
        Imf::addChromaticities(header, rec709());
        Imf::FrameBuffer frame;
        // OpenEXR writes a slice of the channel's own type only: half channels get half copies.
        std::vector<std::vector<Imath::half>> halves;
        halves.reserve(image.channels.size());
        for (const LayeredImage::Channel &c : image.channels) {
            if (c.values.size() != w.area())
                throw std::logic_error(fmt::format("channel {} has the wrong size", c.name));
            if (format.halfChannels.contains(c.name)) {
                header.channels().insert(c.name, Imf::Channel(Imf::HALF));
                halves.emplace_back(c.values.begin(), c.values.end());
                frame.insert(c.name,
                             Imf::Slice(Imf::HALF, sliceBase(halves.back(), w), sizeof(Imath::half),
                                        sizeof(Imath::half) * size_t(w.width())));
            } else {
                header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
                frame.insert(
                    c.name,
                    Imf::Slice(Imf::FLOAT, sliceBase(c.values, w), sizeof(float), sizeof(float) * size_t(w.width())));
            }
        }
        Imf::OutputFile out(stream, header);
        out.setFrameBuffer(frame);
        out.writePixels(w.height());
    } catch (const std::logic_error &) {
        throw;
    } catch (const std::exception &e) {
        throw std::runtime_error(fmt::format("{}: {}", file.string(), e.what()));
    }
    writeBytesAtomically(file, stream.bytes().data(), stream.bytes().size());
}

LayeredImage readExr(const std::filesystem::path &file, ExrFormat *format) {
    try {
        Imf::InputFile in(file.c_str());
        const Imf::Header &header = in.header();
        LayeredImage image;
        PixelWindow display = toWindow(header.displayWindow());
        if (display.x0 != 0 || display.y0 != 0) {
            throw std::runtime_error("the display window does not start at (0, 0)");
        }
        image.fullWidth = display.x1;
        image.fullHeight = display.y1;
        image.dataWindow = toWindow(header.dataWindow());
        const PixelWindow &w = image.dataWindow;
        readMetadata(header, image);
        if (format) {
            format->compression = compressionOf(header.compression());
            format->halfChannels.clear();
        }
        Imf::FrameBuffer frame;
        for (auto c = header.channels().begin(); c != header.channels().end(); ++c) {
            if (format && c.channel().type == Imf::HALF) format->halfChannels.insert(c.name());
            std::vector<float> &values = image.addChannel(c.name());
            frame.insert(
                c.name(),
                Imf::Slice(Imf::FLOAT, sliceBase(values, w), sizeof(float), sizeof(float) * size_t(w.width())));
        }
        in.setFrameBuffer(frame);
        in.readPixels(w.y0, w.y1 - 1);
        return image;
    } catch (const std::exception &e) {
        throw std::runtime_error(fmt::format("{}: {}", file.string(), e.what()));
    }
}

}  // namespace veduta
