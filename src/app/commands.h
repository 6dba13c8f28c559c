// The subcommands of the `veduta` program. Each registers its options with CLI11 and runs
// when chosen; exit codes are the ones documented in README.md.
#pragma once

#include <CLI/CLI.hpp>

namespace veduta {

enum ExitCode : int {
    kExitOk = 0,
    kExitBadInput = 1,  // a scene or data file is wrong; the message says where
    kExitBadUsage = 2,  // the command line is wrong
    kExitFailure = 3,   // output could not be written, or an internal error
};

void addRenderCommand(CLI::App &app, int &exitCode);
void addPreviewCommand(CLI::App &app, int &exitCode);
void addDiffCommand(CLI::App &app, int &exitCode);  // in the veduta-diff program
// Replaces this process with veduta-diff, passing argv on; returns only if that fails.
int runDiffProgram(int argc, char **argv);
void addInfoCommand(CLI::App &app, int &exitCode);
void addCubemapCommand(CLI::App &app, int &exitCode);
void addMergeCommand(CLI::App &app, int &exitCode);
void addFacadeCommand(CLI::App &app, int &exitCode);
void addBuildingCommand(CLI::App &app, int &exitCode);
void addExportCommand(CLI::App &app, int &exitCode);
void addAtkisCommand(CLI::App &app, int &exitCode);
void addCrsCommand(CLI::App &app, int &exitCode);
void addTwinCommand(CLI::App &app, int &exitCode);
void addCompareCommand(CLI::App &app, int &exitCode);
void addGenerateCommand(CLI::App &app, int &exitCode);
void addFarmCommand(CLI::App &app, int &exitCode);

}  // namespace veduta
