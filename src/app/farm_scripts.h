// The two batch scripts of a farm job: the job array that renders the parts, and the merge
// that runs once all of them have succeeded. Plain bash with #SBATCH lines, readable and
// resubmittable by hand (`sbatch --array=3 render.sbatch`).
#pragma once

#include <string>

#include "app/farm_job.h"

namespace veduta {

// `text` as one bash word: in single quotes, each ' written as '\''.
std::string shellQuoted(const std::string &text);

// Every #SBATCH value goes on a line of its own, and the log paths may hold no % patterns
// Slurm would expand: InputError naming the option when one does not fit.
void checkSbatchValues(const FarmJob &job);

std::string taskScript(const FarmJob &job);
std::string mergeScript(const FarmJob &job);

}  // namespace veduta
