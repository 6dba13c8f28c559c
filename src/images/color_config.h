// The OpenColorIO configuration the image plugin converts with: $OCIO when set (as OpenImageIO
// and Blender do), else veduta's own (src/images/veduta.ocio, compiled in), whose colour spaces
// carry Blender's names. Everything is converted to the config's scene_linear space.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <OpenColorIO/OpenColorIO.h>

#include "core/image.h"

namespace veduta {

// The text of src/images/veduta.ocio.
extern const char *const kVedutaOcioConfig;

// What messages and metadata call the compiled-in config.
inline constexpr const char *kBuiltInConfigName = "veduta.ocio (built in)";

// Applies `processor` to the pixels' colour: the first three channels, or the first one as
// grey; further channels such as alpha are left as they are.
void applyToColor(const OCIO_NAMESPACE::ConstCPUProcessorRcPtr &processor, Image &image);

class ColorConfig {
  public:
    // Throws std::runtime_error when $OCIO names a config that cannot be read or is invalid.
    static std::shared_ptr<const ColorConfig> load();
    // A config the user names: throws InputError naming the file when it cannot be read, is
    // invalid or has no scene_linear role.
    static std::shared_ptr<const ColorConfig> loadFile(const std::filesystem::path &file);
    // Throws std::runtime_error when the config has no scene_linear role.
    explicit ColorConfig(OCIO_NAMESPACE::ConstConfigRcPtr config, std::string source = kBuiltInConfigName);

    const OCIO_NAMESPACE::ConstConfigRcPtr &ocio() const { return config_; }
    // Where the config came from: its file, or kBuiltInConfigName.
    const std::string &source() const { return source_; }

    // The colour space's own name for a name, alias or role; nothing when the config lacks it.
    std::optional<std::string> find(const std::string &name) const;
    const std::string &linear() const { return linear_; }
    // A comma-separated list of the config's colour spaces, for messages.
    std::string names() const;

    // Converts the colour channels (the first three, or the first one as grey) in place;
    // further channels such as alpha are left as they are. The names must be known.
    void toLinear(Image &image, const std::string &colorSpace) const;
    void fromLinear(Image &image, const std::string &colorSpace) const;

  private:
    void convert(Image &image, const std::string &from, const std::string &to) const;

    OCIO_NAMESPACE::ConstConfigRcPtr config_;
    std::string source_;
    std::string linear_;
};

}  // namespace veduta
