#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/version.h"
#include "core/memory_limit.h"
#include "io/gdal_guard.h"

int main(int argc, char **argv) {
    if (argc > 1 && std::strcmp(argv[1], "diff") == 0) return veduta::runDiffProgram(argc, argv);
    // Before anything is allocated: past the budget, allocations fail and the command names
    // what ran out, where the kernel's OOM killer would end it without a word.
    try {
        veduta::limitMemory(veduta::memoryBudget());
        veduta::gdalTimeLimit();  // a limit that does not read is an error now, not at the first GDAL file
    } catch (const std::invalid_argument &e) {
        std::fprintf(stderr, "veduta: error: %s\n", e.what());
        return veduta::kExitBadUsage;
    }
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
    veduta::addTwinCommand(app, exitCode);
    veduta::addCompareCommand(app, exitCode);
    veduta::addGenerateCommand(app, exitCode);
    veduta::addFarmCommand(app, exitCode);
    return veduta::runApp(app, argc, argv, exitCode);
}
