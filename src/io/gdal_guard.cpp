#include "io/gdal_guard.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "core/error.h"
#include "core/input_file.h"

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

// Where the prolog's DOCTYPE starts, npos if the prolog has none. Throws when the prolog
// does not end within the text.
size_t doctypeOffset(const std::filesystem::path &file, std::string_view text) {
    size_t at = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    auto skipTo = [&](std::string_view end) {
        size_t found = text.find(end, at);
        if (found == std::string_view::npos)
            throw InputError(locationOf(file, text, at),
                             "a comment or processing instruction before the XML root element does not end (within "
                             "the first MiB); veduta does not give such a file to GDAL");
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
        } else if (rest.starts_with("<!DOCTYPE")) {
            return at;
        } else {
            return std::string_view::npos;  // the root element, or not XML after all
        }
    }
}

}  // namespace

void checkFileForGdal(const std::filesystem::path &file) {
    checkInputFile(file);
    std::string text = head(file, kMaxProlog);
    size_t start = text.find_first_not_of(" \t\r\n", text.starts_with("\xEF\xBB\xBF") ? 3 : 0);
    if (start == std::string::npos || text[start] != '<') return;
    size_t doctype = doctypeOffset(file, text);
    if (doctype == std::string::npos) return;
    throw InputError(locationOf(file, text, doctype),
                     "the XML file has a document type declaration (<!DOCTYPE>); its entities could expand "
                     "without bound, so veduta does not give it to GDAL (NAS, GML and OSM files have none: "
                     "remove it)");
}

std::chrono::milliseconds gdalTimeLimit() {
    if (const char *text = std::getenv("VEDUTA_GDAL_TIME_LIMIT")) {
        char *end = nullptr;
        double seconds = std::strtod(text, &end);
        if (end != text && *end == '\0' && seconds > 0 && seconds < 1e9)
            return std::chrono::milliseconds(int64_t(seconds * 1000));
        throw std::invalid_argument(
            fmt::format("VEDUTA_GDAL_TIME_LIMIT is '{}', not a positive number of seconds such as 600", text));
    }
    return std::chrono::seconds(300);
}

GdalDeadline::GdalDeadline(const std::filesystem::path &file, std::chrono::milliseconds limit) {
    watch_ = std::thread([this, name = file.string(), limit] {
        std::unique_lock lock(mutex_);
        if (finished_.wait_for(lock, limit, [this] { return done_; })) return;
        std::fprintf(stderr,
                     "veduta: %s: GDAL has read this file for %g s without finishing; giving up (a damaged or "
                     "hostile file? VEDUTA_GDAL_TIME_LIMIT sets the limit in seconds)\n",
                     name.c_str(), double(limit.count()) / 1000);
        std::fflush(stderr);
        std::_Exit(1);
    });
}

GdalDeadline::~GdalDeadline() {
    {
        std::lock_guard lock(mutex_);
        done_ = true;
    }
    finished_.notify_one();
    watch_.join();
}

}  // namespace veduta
