#include "app/farm_status.h"

#include <gtest/gtest.h>

namespace veduta {
namespace {

TEST(FarmStatus, AResultOnDiskIsDoneWhateverSlurmRemembers) {
    StepStatus s = stepStatus({true, 1, {{"job", 0, "FAILED", "NonZeroExitCode"}}, true});
    EXPECT_EQ(s.progress, StepProgress::Done);
    EXPECT_EQ(s.text, "done");
}

TEST(FarmStatus, ALiveEntryWinsOverAnEarlierFailure) {
    // A task resubmitted after failing: the old run's record and entry, and the new pending one.
    StepStatus s =
        stepStatus({false, 1, {{"job", 3, "FAILED", "NonZeroExitCode"}, {"job", 3, "PENDING", "Priority"}}, true});
    EXPECT_EQ(s.progress, StepProgress::Waiting);
    EXPECT_EQ(s.text, "pending (Priority)");
    EXPECT_EQ(stepStatus({false, std::nullopt, {{"job", 3, "RUNNING", "None"}}, true}).text, "running");
}

TEST(FarmStatus, AMergeWhoseTasksFailedHasFailed) {
    StepStatus s = stepStatus({false, std::nullopt, {{"job-merge", -1, "PENDING", "DependencyNeverSatisfied"}}, true});
    EXPECT_EQ(s.progress, StepProgress::Failed);
}

TEST(FarmStatus, TheRecordedExitStatusOutlivesSlurmsMemory) {
    StepStatus s = stepStatus({false, 3, {}, true});
    EXPECT_EQ(s.progress, StepProgress::Failed);
    EXPECT_EQ(s.text, "failed with exit status 3");
}

TEST(FarmStatus, EndedWithoutItsFileOrForgottenIsFailed) {
    EXPECT_EQ(stepStatus({false, std::nullopt, {{"job", 0, "TIMEOUT", "None"}}, true}).text, "timeout");
    EXPECT_EQ(stepStatus({false, std::nullopt, {{"job", 0, "COMPLETED", "None"}}, true}).text,
              "completed without its file");
    StepStatus lost = stepStatus({false, std::nullopt, {}, true});
    EXPECT_EQ(lost.progress, StepProgress::Failed);
    EXPECT_EQ(lost.text, "lost: not in Slurm's queue and not done");
    EXPECT_EQ(stepStatus({false, std::nullopt, {}, false}).text, "not submitted");
}

TEST(FarmStatus, ExitCodesFollowTheMergeAndTheTasks) {
    FarmJob job;
    job.folder = "/nonexistent/job.farm";
    job.output = "/nonexistent/job.exr";
    job.name = "veduta-job";
    job.arrayJobId = "7";
    job.tasks = {{"--region", "0", "0", "1", "1"}, {"--region", "1", "0", "2", "1"}};
    FarmStatus waiting = farmStatus(job,
                                    {{"veduta-job", 0, "RUNNING", "None"},
                                     {"veduta-job", 1, "PENDING", "Resources"},
                                     {"veduta-job-merge", -1, "PENDING", "Dependency"},
                                     {"other", 0, "FAILED", "None"}});
    EXPECT_EQ(waiting.exitCode, kExitInProgress);
    ASSERT_EQ(waiting.lines.size(), 4u);
    EXPECT_EQ(waiting.lines[1], "task 1: --region 1 0 2 1: pending (Resources)");
    EXPECT_EQ(waiting.lines[3], "2 tasks: 0 done, 0 failed, 2 queued or running; merge pending (Dependency)");
    FarmStatus failed = farmStatus(job,
                                   {{"veduta-job", 0, "FAILED", "NonZeroExitCode"},
                                    {"veduta-job", 1, "RUNNING", "None"},
                                    {"veduta-job-merge", -1, "PENDING", "Dependency"}});
    EXPECT_EQ(failed.exitCode, 1);
    EXPECT_EQ(failed.lines[0],
              "task 0: --region 0 0 1 1: failed (NonZeroExitCode), log /nonexistent/job.farm/logs/task-0.log");
}

}  // namespace
}  // namespace veduta
