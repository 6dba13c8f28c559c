// What every fuzz target shares: the input as a file (most readers take a path, as users give
// them), and the one outcome bad input may have besides success, an InputError.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/error.h"

namespace veduta::fuzz {

// Writes the input to one file of this process, named with `extension` (".obj"), and returns
// its path. Each call replaces the last input.
std::filesystem::path inputFile(const uint8_t *data, size_t size, std::string_view extension);

// A folder of this process for files an input refers to (includes, textures): empty, so that a
// reference in a mutated input finds nothing rather than the fuzzer's own files.
std::filesystem::path emptyFolder();

inline std::string inputText(const uint8_t *data, size_t size) {
    return std::string(reinterpret_cast<const char *>(data), size);
}

// Runs `read`; an InputError (the message a user gets) is a correct answer to bad input. Any
// other exception escapes and libFuzzer reports it as a crash: bad input must be named.
template <typename Read>
void expectInputError(Read &&read) {
    try {
        read();
    } catch (const InputError &) {}
}

}  // namespace veduta::fuzz
