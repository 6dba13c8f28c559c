#include "facade/description_text.h"

#include <gtest/gtest.h>

#include <string>

namespace veduta {
namespace {

std::string errorOf(std::string_view text) {
    try {
        readDescriptionBlocks(text, "wall.txt");
    } catch (const InputError &error) {
        return error.what();
    }
    return "no error";
}

TEST(DescriptionText, ReadsTheBrickBondOfFigure5_7) {
    // digest-001 §2.5, Fig. 5.7 verbatim.
    auto blocks = readDescriptionBlocks(R"(Brick1 { 2.0, 0.5, 0.1; 206,78,51; 255,147,124; }
Brick2 { 2.0, 1.0, 0.1; 206,78,51; 255,147,124; }
Pattern { -1.0, "Brick1", "Brick2"; 0.0, "Brick1", 2.0; 1.0, "Brick1"; }
BrickMasonry { "Pattern"; 0.05; 102,102,102; })",
                                        "bond.txt");
    ASSERT_EQ(blocks.size(), 4u);
    EXPECT_EQ(blocks[0].name, "Brick1");
    ASSERT_EQ(blocks[0].items.size(), 3u);
    EXPECT_EQ(blocks[0].items[0].number(1, "height"), 0.5);
    EXPECT_EQ(blocks[0].items[2].number(2, "blue"), 124);
    const DescriptionBlock &pattern = blocks[2];
    ASSERT_EQ(pattern.items.size(), 3u);
    EXPECT_EQ(pattern.items[0].number(0, "offset"), -1.0);
    EXPECT_EQ(pattern.items[0].string(2, "brick"), "Brick2");
    EXPECT_EQ(pattern.items[1].fields[2].kind, DescriptionField::Kind::Number);
    EXPECT_EQ(pattern.loc.line, 3);
    EXPECT_EQ(pattern.items[1].loc.line, 3);
    EXPECT_EQ(pattern.items[1].loc.column, 37);
    EXPECT_EQ(blocks[3].items[0].string(0, "pattern"), "Pattern");
}

TEST(DescriptionText, ReadsWordsAndTheLastItemWithoutItsSemicolon) {
    auto blocks = readDescriptionBlocks("# a cornice\nModifications { line, rel, 90, 0.3; arc, abs, 90, 45, 0.5 }", "");
    ASSERT_EQ(blocks.size(), 1u);
    ASSERT_EQ(blocks[0].items.size(), 2u);
    EXPECT_EQ(blocks[0].items[1].word(0, "kind"), "arc");
    EXPECT_EQ(blocks[0].items[1].number(4, "radius"), 0.5);
    EXPECT_EQ(blocks[0].loc.line, 2);
}

TEST(DescriptionText, NamesThePlaceOfWhatIsWrong) {
    EXPECT_EQ(errorOf("Brick { 2.0, 0.5\n  0.1; }"), "wall.txt:2:3: expected ',', ';' or '}' after a field, found '0'");
    EXPECT_EQ(errorOf("Brick { 2.0; "), "wall.txt:1:14: the block 'Brick' has no closing '}'");
    EXPECT_EQ(errorOf("Brick 2.0; }"), "wall.txt:1:7: expected '{' after the block's name, found '2'");
    EXPECT_EQ(errorOf("P { \"Brick1, 2; }"), "wall.txt:1:5: a string does not end");
    EXPECT_EQ(errorOf("P { 1e999; }"), "wall.txt:1:5: not a finite number");
    EXPECT_EQ(errorOf("P { 2.0x; }"), "wall.txt:1:8: a number runs on into 'x'");
    EXPECT_EQ(errorOf("P { ; }"), "wall.txt:1:5: expected a number, a quoted string or a word, found ';'");
    EXPECT_EQ(errorOf("{ 1; }"), "wall.txt:1:1: expected the name of a block, found '{'");
}

TEST(DescriptionText, ItemsNameTheFieldTheyLack) {
    auto blocks = readDescriptionBlocks("Brick { 2.0, \"x\"; }", "b.txt");
    const DescriptionItem &item = blocks[0].items[0];
    try {
        item.number(1, "the height");
        FAIL() << "a string read as a number";
    } catch (const InputError &error) {
        EXPECT_STREQ(error.what(), "b.txt:1:14: expected the height (a number), found a quoted string 'x'");
    }
    try {
        item.number(2, "the depth");
        FAIL() << "a missing field read";
    } catch (const InputError &error) {
        EXPECT_STREQ(error.what(), "b.txt:1:9: expected the depth (a number) as field 3, but the item has 2 fields");
    }
    EXPECT_THROW(item.expectFieldCount(3, 3, "a brick's size"), InputError);
    EXPECT_NO_THROW(item.expectFieldCount(1, 2, "a brick's size"));
}

TEST(DescriptionText, RefusesAnItemWithTooManyFields) {
    std::string text = "P { ";
    for (size_t i = 0; i <= kDescriptionFieldLimit; ++i) text += "1, ";
    text += "1; }";
    EXPECT_NE(errorOf(text).find("more than 64 fields"), std::string::npos);
}

}  // namespace
}  // namespace veduta
