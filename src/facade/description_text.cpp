#include "facade/description_text.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace veduta {
namespace {

bool isWordChar(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}
bool startsNumber(char c) { return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.'; }

std::string describe(char c) {
    if (c >= 0x21 && c <= 0x7e) return fmt::format("'{}'", c);
    return fmt::format("byte 0x{:02x}", static_cast<unsigned char>(c));
}

// Walks the text, tracking line and column for every token it hands out.
class Reader {
  public:
    Reader(std::string_view text, const std::string &file) : text_(text), file_(file) {}

    std::vector<DescriptionBlock> blocks() {
        std::vector<DescriptionBlock> result;
        while (skipSpace(), !atEnd()) {
            if (result.size() == kDescriptionBlockLimit)
                fail(fmt::format("more than {} blocks", kDescriptionBlockLimit));
            result.push_back(block());
        }
        return result;
    }

  private:
    DescriptionBlock block() {
        DescriptionBlock block;
        block.loc = loc();
        if (!isWordChar(peek())) fail(fmt::format("expected the name of a block, found {}", describe(peek())));
        block.name = word();
        expect('{', "after the block's name");
        while (skipSpace(), peek() != '}') {
            if (atEnd()) fail(fmt::format("the block '{}' has no closing '}}'", block.name));
            if (block.items.size() == kDescriptionItemLimit)
                fail(fmt::format("more than {} items in the block '{}'", kDescriptionItemLimit, block.name));
            block.items.push_back(item());
        }
        ++position_;
        return block;
    }

    DescriptionItem item() {
        DescriptionItem item;
        item.loc = loc();
        for (;;) {
            if (item.fields.size() == kDescriptionFieldLimit)
                fail(fmt::format("more than {} fields in one item", kDescriptionFieldLimit));
            item.fields.push_back(field());
            skipSpace();
            if (peek() == ',') {
                ++position_;
                continue;
            }
            if (peek() == ';') ++position_;
            else if (peek() != '}')
                fail(fmt::format("expected ',', ';' or '}}' after a field, found {}", describeNext()));
            return item;
        }
    }

    DescriptionField field() {
        skipSpace();
        DescriptionField field;
        field.loc = loc();
        char c = peek();
        if (c == '"') {
            field.kind = DescriptionField::Kind::String;
            field.text = quotedString();
        } else if (startsNumber(c)) {
            field.kind = DescriptionField::Kind::Number;
            field.number = number(field.text);
        } else if (isWordChar(c)) {
            field.kind = DescriptionField::Kind::Word;
            field.text = word();
        } else {
            fail(fmt::format("expected a number, a quoted string or a word, found {}", describeNext()));
        }
        return field;
    }

    std::string word() {
        size_t start = position_;
        while (isWordChar(peek())) advance();
        return std::string(text_.substr(start, position_ - start));
    }

    double number(std::string &written) {
        size_t start = position_;
        if (peek() == '+') ++position_;  // from_chars takes no plus sign
        double value = 0;
        auto [end, error] = std::from_chars(text_.data() + position_, text_.data() + text_.size(), value);
        if (error != std::errc() || !std::isfinite(value)) {
            position_ = start;
            fail("not a finite number");
        }
        position_ = size_t(end - text_.data());
        if (isWordChar(peek()) || peek() == '.') fail(fmt::format("a number runs on into {}", describeNext()));
        written = std::string(text_.substr(start, position_ - start));
        return value;
    }

    std::string quotedString() {
        FileLoc opening = loc();
        ++position_;
        size_t start = position_;
        while (!atEnd() && peek() != '"') {
            if (peek() == '\n') throw InputError(opening, "a string does not end on its line");
            advance();
        }
        if (atEnd()) throw InputError(opening, "a string does not end");
        std::string result(text_.substr(start, position_ - start));
        ++position_;
        return result;
    }

    void expect(char c, std::string_view context) {
        skipSpace();
        if (peek() != c) fail(fmt::format("expected '{}' {}, found {}", c, context, describeNext()));
        ++position_;
    }

    void skipSpace() {
        for (;;) {
            char c = peek();
            if (c == '#') {
                while (!atEnd() && peek() != '\n') advance();
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
                advance();
            } else {
                return;
            }
        }
    }

    void advance() {
        if (text_[position_] == '\n') {
            ++line_;
            lineStart_ = position_ + 1;
        }
        ++position_;
    }

    bool atEnd() const { return position_ >= text_.size(); }
    char peek() const { return atEnd() ? '\0' : text_[position_]; }
    std::string describeNext() const { return atEnd() ? "the end of the text" : describe(peek()); }
    FileLoc loc() const { return {file_, line_, int(position_ - lineStart_) + 1}; }
    [[noreturn]] void fail(const std::string &message) const { throw InputError(loc(), message); }

    std::string_view text_;
    const std::string &file_;
    size_t position_ = 0;
    size_t lineStart_ = 0;
    int line_ = 1;
};

const char *kindName(DescriptionField::Kind kind) {
    switch (kind) {
    case DescriptionField::Kind::Number: return "a number";
    case DescriptionField::Kind::String: return "a quoted string";
    case DescriptionField::Kind::Word: return "a word";
    }
    return "";
}

const DescriptionField &fieldOf(const DescriptionItem &item, size_t index, DescriptionField::Kind kind,
                                std::string_view what) {
    if (index >= item.fields.size())
        throw InputError(item.loc,
                         fmt::format("expected {} ({}) as field {}, but the item has {} fields", what, kindName(kind),
                                     index + 1, item.fields.size()));
    const DescriptionField &field = item.fields[index];
    if (field.kind != kind)
        throw InputError(
            field.loc,
            fmt::format("expected {} ({}), found {} '{}'", what, kindName(kind), kindName(field.kind), field.text));
    return field;
}

}  // namespace

double DescriptionItem::number(size_t index, std::string_view what) const {
    return fieldOf(*this, index, DescriptionField::Kind::Number, what).number;
}

const std::string &DescriptionItem::string(size_t index, std::string_view what) const {
    return fieldOf(*this, index, DescriptionField::Kind::String, what).text;
}

const std::string &DescriptionItem::word(size_t index, std::string_view what) const {
    return fieldOf(*this, index, DescriptionField::Kind::Word, what).text;
}

void DescriptionItem::expectFieldCount(size_t least, size_t most, std::string_view what) const {
    if (fields.size() >= least && fields.size() <= most) return;
    std::string wanted = least == most ? fmt::format("{}", least) : fmt::format("{} to {}", least, most);
    throw InputError(loc, fmt::format("{} takes {} fields, found {}", what, wanted, fields.size()));
}

std::vector<DescriptionBlock> readDescriptionBlocks(std::string_view text, const std::string &file) {
    return Reader(text, file).blocks();
}

}  // namespace veduta
