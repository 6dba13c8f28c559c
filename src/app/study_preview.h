// Rendering a study scene (study_scene.h) with the preview, for `veduta facade` and
// `veduta building`: the Facade Editor's preview, from the command line.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "description/scene_description.h"

namespace veduta {

struct StudyPreviewOptions {
    std::string output;
    std::string resolution;
    bool noShadows = false;
    bool quiet = false;
};

// -o, --res, --no-shadows, --quiet.
void addStudyPreviewOptions(CLI::App &command, StudyPreviewOptions &options, const std::string &defaultName);

// Builds the scene, previews it with sun shadows and writes the PNG (or EXR); prints a summary
// with the buildings' counts unless quiet.
void previewStudy(SceneDescription scene, const StudyPreviewOptions &options, const std::string &defaultName);

}  // namespace veduta
