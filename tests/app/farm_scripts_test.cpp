#include "app/farm_scripts.h"

#include <filesystem>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "core/error.h"

namespace veduta {
namespace {

FarmJob twoTiles() {
    FarmJob job;
    job.folder = "/shared/it's here.farm";
    job.name = "veduta-x-0001";
    job.program = "/opt/veduta/bin/veduta";
    job.scene = "/shared/scene $(rm -rf).xml";
    job.output = "/shared/x.exr";
    job.renderOptions = {"--spp", "64"};
    job.tasks = {{"--region", "0", "0", "8", "4"}, {"--region", "8", "0", "16", "4"}};
    job.checkpointEvery = 60;
    return job;
}

TEST(FarmScripts, ShellQuotingKeepsEveryCharacter) {
    EXPECT_EQ(shellQuoted("plain"), "'plain'");
    EXPECT_EQ(shellQuoted("it's $(x) `y` \"z\""), "'it'\\''s $(x) `y` \"z\"'");
}

TEST(FarmScripts, TasksResumeFromTheirCheckpointsWhenRequeued) {
    std::string script = taskScript(twoTiles());
    EXPECT_NE(script.find("#SBATCH --requeue\n"), std::string::npos);
    EXPECT_NE(script.find("#SBATCH --array=0-1\n"), std::string::npos);
    EXPECT_NE(script.find("--checkpoint-every 60 --resume -o \"$part\"\n"), std::string::npos);
    EXPECT_NE(script.find("'/opt/veduta/bin/veduta' 'render' '/shared/scene $(rm -rf).xml' '--spp' '64'"),
              std::string::npos);
    EXPECT_NE(script.find("1) task=('--region' '8' '0' '16' '4') ;;\n"), std::string::npos);
}

TEST(FarmScripts, TheMergeNamesEveryPart) {
    std::string script = mergeScript(twoTiles());
    EXPECT_NE(script.find("#SBATCH --job-name=veduta-x-0001-merge\n"), std::string::npos);
    EXPECT_NE(script.find("'merge' '/shared/x.exr' '/shared/it'\\''s here.farm/parts/part-0.exr' "
                          "'/shared/it'\\''s here.farm/parts/part-1.exr'\n"),
              std::string::npos);
}

TEST(FarmScripts, SlurmValuesThatDoNotFitAreRefused) {
    FarmJob job = twoTiles();
    EXPECT_NO_THROW(checkSbatchValues(job));
    job.folder = "/shared/100%.farm";
    EXPECT_THROW(checkSbatchValues(job), InputError);
    job = twoTiles();
    job.slurm.extra = {"qos=long"};
    EXPECT_THROW(checkSbatchValues(job), InputError);
}

TEST(FarmScripts, TheJobFileReadsBack) {
    FarmJob job = twoTiles();
    job.arrayJobId = "17";
    job.mergeJobId = "18";
    std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("veduta_farm_job_test_" + std::to_string(getpid()));
    std::filesystem::create_directories(folder);
    job.folder = folder;
    FILE *file = std::fopen(jobFilePath(folder).c_str(), "w");
    ASSERT_TRUE(file);
    std::string text = jobFileText(job);
    std::fwrite(text.data(), 1, text.size(), file);
    std::fclose(file);
    FarmJob read = readJobFile(folder);
    std::filesystem::remove_all(folder);
    EXPECT_EQ(read.name, job.name);
    EXPECT_EQ(read.scene, job.scene);
    EXPECT_EQ(read.output, job.output);
    EXPECT_EQ(read.arrayJobId, "17");
    EXPECT_EQ(read.mergeJobId, "18");
    EXPECT_EQ(read.tasks, job.tasks);
    EXPECT_THROW(readJobFile(folder), InputError);
}

}  // namespace
}  // namespace veduta
