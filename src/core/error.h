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
    InputError(const FileLoc &loc, const std::string &message) :
        std::runtime_error(loc.toString() + ": " + message), loc_(loc), message_(message) {}
    const FileLoc &loc() const { return loc_; }
    // What is wrong, without the place: for a caller that knows the place better.
    const std::string &message() const { return message_; }

  private:
    FileLoc loc_;
    std::string message_;
};

}  // namespace veduta
