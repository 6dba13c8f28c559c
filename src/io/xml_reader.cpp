#include "io/xml_reader.h"

#include <algorithm>
#include <charconv>

#include <fmt/format.h>

#include "core/input_file.h"

namespace veduta {

XmlDocument XmlDocument::fromFile(const std::filesystem::path &file) {
    return XmlDocument(readInputFile(file), file.string());
}

XmlDocument XmlDocument::fromString(std::string text, std::string name) {
    return XmlDocument(std::move(text), std::move(name));
}

XmlDocument::XmlDocument(std::string text, std::string name) :
    name_(std::move(name)),
    text_(std::make_unique<std::string>(std::move(text))),
    doc_(std::make_unique<pugi::xml_document>()) {
    lineStarts_.push_back(0);
    for (size_t i = 0; i < text_->size(); ++i) {
        if ((*text_)[i] == '\n') lineStarts_.push_back(i + 1);
    }
    pugi::xml_parse_result result =
        doc_->load_buffer_inplace(text_->data(), text_->size(), pugi::parse_default, pugi::encoding_utf8);
    if (!result) throw InputError(locateOffset(size_t(result.offset)), result.description());
    if (!doc_->document_element()) throw InputError({name_}, "no root element");
}

FileLoc XmlDocument::locateOffset(size_t offset) const {
    auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
    size_t line = size_t(it - lineStarts_.begin());
    return {name_, int(line), int(offset - lineStarts_[line - 1] + 1)};
}

FileLoc XmlDocument::locate(const char *pointerIntoText) const {
    return locateOffset(size_t(pointerIntoText - text_->data()));
}

FileLoc XmlElement::attributeLoc(const char *attribute) const {
    pugi::xml_attribute a = node_.attribute(attribute);
    return a ? doc_->locate(a.value()) : loc();
}

std::string XmlElement::string(const char *attribute) const {
    if (!has(attribute)) fail(fmt::format("<{}> needs the attribute '{}'", name(), attribute));
    markRead(attribute);
    return node_.attribute(attribute).value();
}

std::string XmlElement::string(const char *attribute, const std::string &fallback) const {
    return has(attribute) ? string(attribute) : fallback;
}

template <typename T>
T XmlElement::parseNumber(const char *attribute, std::string_view token) const {
    T value = 0;
    auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) {
        failAt(attribute, fmt::format("'{}' is not a number (attribute '{}')", token, attribute));
    }
    return value;
}

template <typename T>
std::vector<T> XmlElement::parseList(const char *attribute) const {
    std::string text = string(attribute);
    std::vector<T> values;
    size_t pos = 0;
    while (true) {
        pos = text.find_first_not_of(" \t\r\n,", pos);
        if (pos == std::string::npos) break;
        size_t end = text.find_first_of(" \t\r\n,", pos);
        if (end == std::string::npos) end = text.size();
        values.push_back(parseNumber<T>(attribute, std::string_view(text).substr(pos, end - pos)));
        pos = end;
    }
    return values;
}

std::vector<float> XmlElement::numbers(const char *attribute) const { return parseList<float>(attribute); }
std::vector<double> XmlElement::doubles(const char *attribute) const { return parseList<double>(attribute); }

float XmlElement::number(const char *attribute, float fallback) const {
    if (!has(attribute)) return fallback;
    std::vector<float> values = numbers(attribute);
    if (values.size() != 1) failAt(attribute, fmt::format("attribute '{}' takes one number", attribute));
    return values[0];
}

float XmlElement::number(const char *attribute, float fallback, float lo, float hi) const {
    float value = number(attribute, fallback);
    if (value < lo || value > hi) {
        failAt(attribute, fmt::format("attribute '{}' is {}, outside [{}, {}]", attribute, value, lo, hi));
    }
    return value;
}

namespace {

std::string trimmed(const std::string &text) {
    size_t begin = text.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos) return {};
    return text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1);
}

}  // namespace

int XmlElement::integer(const char *attribute, int fallback, int lo, int hi) const {
    if (!has(attribute)) return fallback;
    std::string text = trimmed(string(attribute));
    long long value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) {
        failAt(attribute, fmt::format("'{}' is not an integer (attribute '{}')", text, attribute));
    }
    if (value < lo || value > hi) {
        failAt(attribute, fmt::format("attribute '{}' is {}, outside [{}, {}]", attribute, value, lo, hi));
    }
    return int(value);
}

bool XmlElement::boolean(const char *attribute, bool fallback) const {
    if (!has(attribute)) return fallback;
    std::string text = trimmed(string(attribute));
    if (text == "true" || text == "1") return true;
    if (text == "false" || text == "0") return false;
    failAt(attribute, fmt::format("'{}' is not true or false (attribute '{}')", text, attribute));
}

uint32_t XmlElement::unsignedInteger(const char *attribute, uint32_t fallback) const {
    if (!has(attribute)) return fallback;
    std::string text = trimmed(string(attribute));
    uint32_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) {
        failAt(attribute, fmt::format("'{}' is not an unsigned 32-bit integer (attribute '{}')", text, attribute));
    }
    return value;
}

Vec3f XmlElement::vec3(const char *attribute, Vec3f fallback) const {
    if (!has(attribute)) return fallback;
    std::vector<float> v = numbers(attribute);
    if (v.size() != 3) failAt(attribute, fmt::format("attribute '{}' takes three numbers", attribute));
    return {v[0], v[1], v[2]};
}

Vec3f XmlElement::color(const char *attribute, Vec3f fallback) const {
    if (!has(attribute)) return fallback;
    std::vector<float> v = numbers(attribute);
    if (v.size() == 1) return Vec3f(v[0]);
    if (v.size() != 3) failAt(attribute, fmt::format("attribute '{}' takes one or three numbers", attribute));
    return {v[0], v[1], v[2]};
}

Vec3f XmlElement::color(const char *attribute, Vec3f fallback, float lo, float hi) const {
    Vec3f value = color(attribute, fallback);
    for (int i = 0; i < 3; ++i) {
        if (value[i] < lo || value[i] > hi) {
            failAt(attribute, fmt::format("attribute '{}' has {}, outside [{}, {}]", attribute, value[i], lo, hi));
        }
    }
    return value;
}

std::vector<XmlElement> XmlElement::children() const {
    std::vector<XmlElement> result;
    for (pugi::xml_node child : node_.children()) {
        if (child.type() == pugi::node_element) result.emplace_back(*doc_, child);
    }
    return result;
}

namespace {

constexpr const char *kXmlSpace = " \t\r\n";

}  // namespace

std::string trimmedXmlText(std::string_view text) {
    size_t first = text.find_first_not_of(kXmlSpace);
    if (first == std::string_view::npos) return "";
    return std::string(text.substr(first, text.find_last_not_of(kXmlSpace) - first + 1));
}

std::string XmlElement::text() const { return trimmedXmlText(node_.child_value()); }

FileLoc XmlElement::textLoc() const {
    const char *raw = node_.child_value();
    std::string_view view(raw);
    size_t first = view.find_first_not_of(kXmlSpace);
    return first == std::string_view::npos || view.empty() ? loc() : doc_->locate(raw + first);
}

void XmlElement::checkAllRead() const {
    for (pugi::xml_attribute a : node_.attributes()) {
        if (std::find(read_.begin(), read_.end(), a.name()) == read_.end()) {
            throw InputError(doc_->locate(a.name()), fmt::format("unknown attribute '{}' on <{}>", a.name(), name()));
        }
        // pugixml keeps both copies of a repeated attribute; lookups would see only the first.
        for (pugi::xml_attribute b = a.next_attribute(); b; b = b.next_attribute()) {
            if (std::string_view(a.name()) == b.name()) {
                throw InputError(doc_->locate(b.name()), fmt::format("attribute '{}' is given twice", b.name()));
            }
        }
    }
}

void XmlElement::checkLeaf() const {
    checkAllRead();
    for (pugi::xml_node child : node_.children()) {
        if (child.type() == pugi::node_element) {
            throw InputError(doc_->locate(child.name() - 1),
                             fmt::format("<{}> cannot stand inside <{}>", child.name(), name()));
        }
    }
}

}  // namespace veduta
