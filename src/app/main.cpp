#include <cstring>

#include <CLI/CLI.hpp>

#include "app/commands.h"
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
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success &e) {
        return app.exit(e);
    } catch (const CLI::ParseError &e) {
        app.exit(e);
        return veduta::kExitBadUsage;
    }
    return exitCode;
}
