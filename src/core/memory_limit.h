// veduta's memory budget: a limit on the process's data (heap and private mappings), so that a
// scene or file too large for the machine ends in an error naming what ran out rather than in
// the kernel's OOM killer, which gives no message and may take other programs with it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace veduta {

// "8G", "512M", "2.5g", "1000000" (bytes): the size in bytes; nullopt for anything else.
std::optional<uint64_t> parseMemorySize(std::string_view text);

// VEDUTA_MAX_MEMORY if it is set (an error if it is no size), else 90 % of the machine's
// physical memory.
uint64_t memoryBudget();

// Sets the process's RLIMIT_DATA to `bytes` (lowering only; a lower limit set by the caller
// stays). Returns the limit in force.
uint64_t limitMemory(uint64_t bytes);

// The RLIMIT_DATA in force, nullopt when there is none.
std::optional<uint64_t> memoryLimit();

// "8.0 GB": what messages say.
std::string memorySizeText(uint64_t bytes);

}  // namespace veduta
