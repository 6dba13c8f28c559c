#include <cstring>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/version.h"

int main(int argc, char **argv) {
    if (argc > 1 && std::strcmp(argv[1], "diff") == 0) return veduta::runDiffProgram(argc, argv);
    CLI::App app{"veduta: an offline renderer for landscape and city stills"};
    app.set_version_flag("--version", std::string("veduta ") + veduta::kVersion);
    app.require_subcommand(1);
    int exitCode = veduta::kExitOk;
    veduta::addRenderCommand(app, exitCode);
    veduta::addPreviewCommand(app, exitCode);
    // Listed here for --help; it runs as its own program (runDiffProgram above).
    app.add_subcommand("diff", "Compare two images and say whether they agree (see veduta diff --help)");
    veduta::addInfoCommand(app, exitCode);
    veduta::addCubemapCommand(app, exitCode);
    veduta::addMergeCommand(app, exitCode);
    veduta::addFacadeCommand(app, exitCode);
    veduta::addBuildingCommand(app, exitCode);
    veduta::addExportCommand(app, exitCode);
    veduta::addAtkisCommand(app, exitCode);
    veduta::addCrsCommand(app, exitCode);
    return veduta::runApp(app, argc, argv, exitCode);
}
