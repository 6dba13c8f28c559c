#include "app/command_options.h"

#include <cstdio>
#include <exception>
#include <filesystem>

#include <fmt/format.h>

#include "core/error.h"

namespace veduta {

std::string checkResolution(const std::string &text) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 || w > 65536 ||
        h > 65536) {
        return fmt::format("'{}' is not a resolution like 1920x1080", text);
    }
    return {};
}

CLI::Validator fileWithExtension(const std::string &extension) {
    return CLI::Validator(
        [extension](const std::string &text) {
            return std::filesystem::path(text).extension() == extension
                ? std::string()
                : fmt::format("'{}' is not a {} file", text, extension);
        },
        "FILE" + extension);
}

int epsgOption(const std::string &text, const std::string &option) {
    if (text.empty()) return 0;
    std::string digits = text.rfind("EPSG:", 0) == 0 || text.rfind("epsg:", 0) == 0 ? text.substr(5) : text;
    try {
        size_t used = 0;
        int code = std::stoi(digits, &used);
        if (used == digits.size() && code > 0) return code;
    } catch (const std::exception &) {}
    throw InputError(FileLoc{option}, fmt::format("'{}' is no CRS; give EPSG:<code>", text));
}

void addSceneArgument(CLI::App &command, std::string &scene) {
    command.add_option("scene", scene, "Scene file (XML); the built-in default scene when omitted")
        ->check(CLI::ExistingFile);
}

void addResolutionOption(CLI::App &command, std::string &resolution) {
    command.add_option("--res", resolution, "Resolution WxH (overrides the scene)")
        ->check(CLI::Validator(checkResolution, "WxH"));
}

void addThreadsOption(CLI::App &command, unsigned &threads) {
    command.add_option("--threads", threads, "Worker threads [all cores]")->check(CLI::Range(1u, 4096u));
}

void applyResolution(const std::string &text, Camera &camera) {
    if (!text.empty()) std::sscanf(text.c_str(), "%dx%d", &camera.width, &camera.height);
}

std::unique_ptr<tbb::global_control> limitThreads(unsigned threads) {
    if (threads == 0) return nullptr;
    return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
}

std::string defaultOutput(const std::string &scene, const std::string &suffix) {
    std::string stem = scene.empty() ? "default" : std::filesystem::path(scene).stem().string();
    return fmt::format("renders/{}{}", stem, suffix);
}

}  // namespace veduta
