// `veduta facade`: one facade of a rule set, previewed in a second.
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/number_option.h"
#include "app/run_guarded.h"
#include "app/study_preview.h"
#include "app/study_scene.h"

namespace veduta {

namespace {

struct FacadeArgs {
    StudyOptions study;
    StudyPreviewOptions preview;
    std::string start = "FrontFacade";
    float width = 15, height = 16;
};

}  // namespace

void addFacadeCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<FacadeArgs>();
    CLI::App *cmd = app.add_subcommand("facade", "Derive one facade from a rule file and preview it, to PNG");
    addStudyOptions(*cmd, args->study);
    cmd->add_option("--start", args->start, "Start symbol [FrontFacade]");
    cmd->add_option("--width", args->width, "Facade width in metres [15]")->check(finiteIn(0.1, 1000));
    cmd->add_option("--height", args->height, "Facade height in metres [16]")->check(finiteIn(0.1, 1000));
    addStudyPreviewOptions(*cmd, args->preview, "facade.png");
    cmd->callback([args, &exitCode] {
        exitCode = runGuarded([&] {
            previewStudy(facadeStudy(args->study, args->start, args->width, args->height), args->preview, "facade.png");
        });
    });
}

}  // namespace veduta
