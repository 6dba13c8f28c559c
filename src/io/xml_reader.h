// Reading XML inputs (scene files, later rule files) with every value tied to its place in
// the file. pugixml parses in place, so element names and attribute values point into our
// own buffer and their byte offsets give exact line:column positions for messages.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

#include "core/error.h"
#include "core/vecmath.h"

namespace veduta {

// `text` without the XML white space (space, tab, CR, LF) at either end.
std::string trimmedXmlText(std::string_view text);

class XmlDocument {
  public:
    static XmlDocument fromFile(const std::filesystem::path &file);
    // `name` is what messages call the text, e.g. "<built-in default scene>".
    static XmlDocument fromString(std::string text, std::string name);

    pugi::xml_node root() const { return doc_->document_element(); }
    const std::string &name() const { return name_; }
    FileLoc locate(const char *pointerIntoText) const;
    FileLoc locateOffset(size_t offset) const;

  private:
    XmlDocument(std::string text, std::string name);

    std::string name_;
    std::unique_ptr<std::string> text_;  // pugixml's nodes point into it: keep its address fixed
    std::vector<size_t> lineStarts_;
    std::unique_ptr<pugi::xml_document> doc_;
};

// One element, read attribute by attribute. Every attribute must be read by the code that
// handles the element; checkAllRead() reports the rest, so a typo is an error, not a default.
class XmlElement {
  public:
    XmlElement(const XmlDocument &doc, pugi::xml_node node) : doc_(&doc), node_(node) {}

    std::string_view name() const { return node_.name(); }
    FileLoc loc() const { return doc_->locate(node_.name() - 1); }
    FileLoc attributeLoc(const char *attribute) const;
    [[noreturn]] void fail(const std::string &message) const { throw InputError(loc(), message); }
    [[noreturn]] void failAt(const char *attribute, const std::string &message) const {
        throw InputError(attributeLoc(attribute), message);
    }

    bool has(const char *attribute) const { return bool(node_.attribute(attribute)); }
    std::string string(const char *attribute) const;  // required
    std::string string(const char *attribute, const std::string &fallback) const;
    float number(const char *attribute, float fallback) const;
    float number(const char *attribute, float fallback, float lo, float hi) const;
    int integer(const char *attribute, int fallback, int lo, int hi) const;
    bool boolean(const char *attribute, bool fallback) const;  // true/false/1/0
    uint32_t unsignedInteger(const char *attribute, uint32_t fallback) const;
    Vec3f vec3(const char *attribute, Vec3f fallback) const;
    // Three numbers, or one number meaning all three.
    Vec3f color(const char *attribute, Vec3f fallback) const;
    Vec3f color(const char *attribute, Vec3f fallback, float lo, float hi) const;  // each component
    std::vector<float> numbers(const char *attribute) const;
    // The same in double precision, for map coordinates (float resolves only ~0.5 m there).
    std::vector<double> doubles(const char *attribute) const;

    std::vector<XmlElement> children() const;
    // The element's text, trimmed (<Symbol>\n  Wall0.wrl\n</Symbol> reads "Wall0.wrl"), and
    // where it starts; the element's place when it has none.
    std::string text() const;
    FileLoc textLoc() const;
    // Reports attributes nobody read, and attributes given twice.
    void checkAllRead() const;
    // checkAllRead(), and reports child elements: for elements that hold none.
    void checkLeaf() const;

  private:
    void markRead(const char *attribute) const { read_.emplace_back(attribute); }
    template <typename T>
    T parseNumber(const char *attribute, std::string_view token) const;
    template <typename T>
    std::vector<T> parseList(const char *attribute) const;

    const XmlDocument *doc_;
    pugi::xml_node node_;
    mutable std::vector<std::string> read_;
};

}  // namespace veduta
