// `veduta building`: one building from a footprint and a rule file, previewed.
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/study_preview.h"
#include "app/study_scene.h"

namespace veduta {

namespace {

struct BuildingArgs {
    StudyOptions study;
    BuildingOptions plan;
    StudyPreviewOptions preview;
};

}  // namespace

void addBuildingCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<BuildingArgs>();
    CLI::App *cmd =
        app.add_subcommand("building", "Derive one building from a footprint and a rule file and preview it");
    addStudyOptions(*cmd, args->study);
    addFootprintOptions(*cmd, args->plan);
    addStudyPreviewOptions(*cmd, args->preview, "building.png");
    cmd->callback([args, &exitCode] {
        exitCode =
            runGuarded([&] { previewStudy(buildingStudy(args->study, args->plan), args->preview, "building.png"); });
    });
}

}  // namespace veduta
