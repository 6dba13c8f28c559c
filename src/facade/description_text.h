// The shape Finkenzeller's small description languages share (Defs 5.5–5.11: Brick, Pattern,
// BrickMasonry, AshlarMasonry, Modifications, Consoles, TexturePool): named blocks
// `Name { field, field; field; … }` of items ended by `;` whose fields are separated by `,`, each a
// number, a quoted string or a bare word. This reads that shape once, with the place of every
// token, so that each language's parser checks only its own fields and every message reads
// `file:line:col: what is wrong`.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace veduta {

struct DescriptionField {
    enum class Kind { Number, String, Word };
    Kind kind = Kind::Word;
    std::string text;   // the string without its quotes, the word, or the number as written
    double number = 0;  // for Kind::Number
    FileLoc loc;
};

struct DescriptionItem {
    std::vector<DescriptionField> fields;
    FileLoc loc;  // of the first field

    // The field at `index` as a number / a quoted string / a bare word; an InputError at the item
    // ("expected <what> as field N") when it is missing or of another kind.
    double number(size_t index, std::string_view what) const;
    const std::string &string(size_t index, std::string_view what) const;
    const std::string &word(size_t index, std::string_view what) const;
    // An InputError at the item unless it has between `least` and `most` fields.
    void expectFieldCount(size_t least, size_t most, std::string_view what) const;
};

struct DescriptionBlock {
    std::string name;
    FileLoc loc;  // of the name
    std::vector<DescriptionItem> items;
};

// The most a description may hold: blocks, items of one block and fields of one item. A text
// past them is refused rather than read into memory without end.
inline constexpr size_t kDescriptionBlockLimit = 10000;
inline constexpr size_t kDescriptionItemLimit = 100000;
inline constexpr size_t kDescriptionFieldLimit = 64;

// Every block of `text`, in order. `#` starts a comment to the end of the line. The last item of
// a block may omit its `;`. Throws InputError at the offending character (`file` names the text;
// lines and columns count from 1, columns in bytes).
std::vector<DescriptionBlock> readDescriptionBlocks(std::string_view text, const std::string &file);

}  // namespace veduta
