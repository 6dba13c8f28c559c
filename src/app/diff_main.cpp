// veduta-diff: the program behind `veduta diff`. It is separate because it links
// OpenImageIO (to read any image format), whose start-up cost the other commands avoid.
// `veduta diff A B ...` runs `veduta-diff diff A B ...`.
#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/version.h"

int main(int argc, char **argv) {
    CLI::App app{"veduta diff: compare two images"};
    app.set_version_flag("--version", std::string("veduta ") + veduta::kVersion);
    app.require_subcommand(1);
    int exitCode = veduta::kExitOk;
    veduta::addDiffCommand(app, exitCode);
    return veduta::runApp(app, argc, argv, exitCode);
}
