// Errors in what users give us (scene files, meshes, command lines). They carry the place
// in the input so that the message reads `file:line:column: what is wrong`.
#pragma once

#include <stdexcept>
#include <string>

namespace veduta {

struct FileLoc {
    std::string file;
    int line = 0;    // 1-based; 0 when unknown
    int column = 0;  // 1-based; 0 when unknown

    std::string toString() const;
};

class InputError : public std::runtime_error {
  public:
    InputError(const FileLoc &loc, const std::string &message)
        : std::runtime_error(loc.toString() + ": " + message), loc_(loc) {}
    const FileLoc &loc() const { return loc_; }

  private:
    FileLoc loc_;
};

}  // namespace veduta
