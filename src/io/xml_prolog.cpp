#include "io/xml_prolog.h"

#include <fstream>
#include <string>

#include "core/error.h"

namespace veduta {

namespace {

// Comments and processing instructions may come before a DOCTYPE; a prolog longer than this
// is refused rather than scanned on.
constexpr size_t kMaxProlog = size_t(1) << 20;

std::string head(const std::filesystem::path &file, size_t bytes) {
    std::ifstream in(file, std::ios::binary);
    std::string text(bytes, '\0');
    in.read(text.data(), std::streamsize(bytes));
    text.resize(size_t(in.gcount()));
    return text;
}

FileLoc locationOf(const std::filesystem::path &file, std::string_view text, size_t offset) {
    FileLoc loc{file.string(), 1, 1};
    for (size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++loc.line;
            loc.column = 1;
        } else {
            ++loc.column;
        }
    }
    return loc;
}

// Where the first markup after the prolog's comments and processing instructions starts (a
// DOCTYPE or the root element), npos if nothing follows them. Throws when the prolog does
// not end within the text.
size_t prologEnd(const std::filesystem::path &file, std::string_view text, std::string_view reader) {
    size_t at = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    auto skipTo = [&](std::string_view end) {
        size_t found = text.find(end, at);
        if (found == std::string_view::npos)
            throw InputError(locationOf(file, text, at),
                             "a comment or processing instruction before the XML root element does not end (within "
                             "the first MiB); veduta does not give such a file to " +
                                 std::string(reader));
        at = found + end.size();
    };
    for (;;) {
        at = text.find_first_not_of(" \t\r\n", at);
        if (at == std::string_view::npos) return std::string_view::npos;
        std::string_view rest = text.substr(at);
        if (rest.starts_with("<?")) {
            skipTo("?>");
        } else if (rest.starts_with("<!--")) {
            skipTo("-->");
        } else {
            return at;
        }
    }
}

// Whether the text starts like XML: its first character after a byte-order mark and
// whitespace is '<'.
bool looksLikeXml(std::string_view text) {
    size_t start = text.find_first_not_of(" \t\r\n", text.starts_with("\xEF\xBB\xBF") ? 3 : 0);
    return start != std::string_view::npos && text[start] == '<';
}

}  // namespace

void refuseDocumentType(const std::filesystem::path &file, std::string_view reader) {
    std::string text = head(file, kMaxProlog);
    if (!looksLikeXml(text)) return;
    size_t doctype = prologEnd(file, text, reader);
    if (doctype == std::string::npos || !std::string_view(text).substr(doctype).starts_with("<!DOCTYPE")) return;
    throw InputError(locationOf(file, text, doctype),
                     "the XML file has a document type declaration (<!DOCTYPE>); its entities could expand "
                     "without bound, so veduta does not give it to " +
                         std::string(reader) + " (NAS, GML, CityGML and OSM files have none: remove it)");
}

std::string rootElementName(const std::filesystem::path &file) {
    std::string text = head(file, kMaxProlog);
    if (!looksLikeXml(text)) return {};
    size_t at = prologEnd(file, text, "an XML parser");
    if (at == std::string::npos || text.compare(at, 2, "<!") == 0) return {};
    size_t end = text.find_first_of(" \t\r\n/>", at + 1);
    return text.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
}

}  // namespace veduta
