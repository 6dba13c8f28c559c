// Options that several subcommands share, so that they read and check them alike.
#pragma once

#include <memory>
#include <string>

#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include "scene/camera.h"

namespace veduta {

// CLI11 validators: an empty string means the text is fine.
std::string checkResolution(const std::string &text);  // WxH
CLI::Validator fileWithExtension(const std::string &extension);

// An EPSG code from "EPSG:25832" (or "25832"); 0 for "". InputError at `option` otherwise.
int epsgOption(const std::string &text, const std::string &option);

// The options several commands take, registered with the same names, checks and help.
void addSceneArgument(CLI::App &command, std::string &scene);          // optional SCENE
void addResolutionOption(CLI::App &command, std::string &resolution);  // --res WxH
void addThreadsOption(CLI::App &command, unsigned &threads);           // --threads N

// Sets the camera's resolution from a WxH text that checkResolution accepted; "" keeps it.
void applyResolution(const std::string &text, Camera &camera);

// Limits TBB (and Embree, which runs on TBB) to `threads` workers while alive; 0 = all cores.
std::unique_ptr<tbb::global_control> limitThreads(unsigned threads);

// renders/<scene file name without extension><suffix>, or renders/default<suffix>.
std::string defaultOutput(const std::string &scene, const std::string &suffix);

}  // namespace veduta
