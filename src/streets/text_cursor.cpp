#include "streets/text_cursor.h"

#include <fmt/format.h>

namespace veduta {

std::string quoted(char c) {
    auto byte = uint8_t(c);
    return byte >= 0x20 && byte < 0x7f ? fmt::format("'{}'", c) : fmt::format("byte {:#04x}", byte);
}

void TextCursor::skipSpace() {
    while (peek() == ' ' || peek() == '\t' || peek() == '\r') advance();
}

bool TextCursor::atEnd() {
    skipSpace();
    return position_ >= text_.size();
}

bool TextCursor::consume(std::string_view token) {
    skipSpace();
    if (!lookingAt(token)) return false;
    advance(token.size());
    return true;
}

void TextCursor::expect(std::string_view token, std::string_view context) {
    if (consume(token)) return;
    fail(fmt::format("expected '{}' {}, found {}", token, context, describeNext()));
}

}  // namespace veduta
