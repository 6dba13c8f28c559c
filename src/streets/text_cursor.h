// A position in one line of a street rule file, shared by the rule and expression parsers so
// that an expression ends where the rule's syntax goes on (`->`, `{`, `:`) and every error
// names its line and column.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>

#include "core/error.h"

namespace veduta {

// The names of variables, defines and labels: a letter or `_`, then letters, digits and `_`.
inline bool isNameStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
inline bool isDigit(char c) { return c >= '0' && c <= '9'; }
inline bool isNameChar(char c) { return isNameStart(c) || isDigit(c); }

// How messages name a character: 'x', or `byte 0x07` for one that does not print.
std::string quoted(char c);

class TextCursor {
  public:
    // `text` is one line without its comment; `file` and `line` name it in messages.
    TextCursor(std::string_view text, std::string file, int line) : text_(text), file_(std::move(file)), line_(line) {}

    void skipSpace();
    bool atEnd();  // after skipping spaces
    // The character `ahead` places on, '\0' past the end; no spaces are skipped.
    char peek(size_t ahead = 0) const { return position_ + ahead < text_.size() ? text_[position_ + ahead] : '\0'; }
    void advance(size_t count = 1) { position_ += count; }
    // Skips spaces; then, if the text goes on with `token`, consumes it.
    bool consume(std::string_view token);
    // The same, failing with "expected <token> <context>" when it does not.
    void expect(std::string_view token, std::string_view context);
    bool lookingAt(std::string_view token) const { return rest().starts_with(token); }
    std::string_view rest() const { return text_.substr(std::min(position_, text_.size())); }

    // The next character as messages name it, or "the end of the line".
    std::string describeNext() const { return position_ < text_.size() ? quoted(peek()) : "the end of the line"; }

    FileLoc loc() const { return {file_, line_, int(position_) + 1}; }
    [[noreturn]] void fail(const std::string &message) const { throw InputError(loc(), message); }

  private:
    std::string_view text_;
    std::string file_;
    int line_;
    size_t position_ = 0;
};

}  // namespace veduta
