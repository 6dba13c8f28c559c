#include "geo/xyz_grid.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "core/error.h"
#include "core/input_file.h"

namespace veduta {

namespace {

// A point may lie this fraction of a spacing off its node (coordinates rounded in the file).
constexpr double kGridTolerance = 0.05;

struct XyzPoint {
    double x = 0, y = 0;
    float height = 0;
    int line = 0, column = 0;  // of the easting
};

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string shown(std::string_view token) {
    return token.size() <= 40 ? std::string(token) : std::string(token.substr(0, 40)) + "…";
}

double parseNumber(std::string_view token, const FileLoc &loc, bool isHeight) {
    std::string_view digits = token.front() == '+' ? token.substr(1) : token;
    double value = 0;
    auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range)
        throw InputError(loc, fmt::format("'{}' is out of range", shown(token)));
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
        throw InputError(loc, fmt::format("'{}' is not a number", shown(token)));
    if (std::isnan(value) && isHeight)
        throw InputError(loc, "the height is NaN; leave out the points that have no height");
    if (!std::isfinite(value)) throw InputError(loc, fmt::format("'{}' is not a finite number", shown(token)));
    if (isHeight && std::abs(value) > kMaxHeight)
        throw InputError(loc,
                         fmt::format("the height {} m lies beyond any on Earth (±{} m)", shown(token), kMaxHeight));
    return value;
}

// Calls visit(point) for every point of `text` in file order until it returns false, checking
// the form of every line.
template <class Visit>
void forEachPoint(std::string_view text, const std::string &file, Visit &&visit) {
    const char *p = text.data(), *end = p + text.size();
    for (int line = 1; p < end; ++line) {
        const char *lineStart = p;
        const char *lineEnd = static_cast<const char *>(std::memchr(p, '\n', size_t(end - p)));
        if (!lineEnd) lineEnd = end;
        p = lineEnd + 1;

        const char *q = lineStart;
        while (q < lineEnd && isBlank(*q)) ++q;
        if (q == lineEnd || *q == '#') continue;
        double values[3] = {0, 0, 0};
        int count = 0, xColumn = int(q - lineStart) + 1;
        while (q < lineEnd) {
            const char *tokenStart = q;
            while (q < lineEnd && !isBlank(*q)) ++q;
            FileLoc loc{file, line, int(tokenStart - lineStart) + 1};
            if (count == 3) throw InputError(loc, "a fourth value; a line holds easting, northing and height");
            values[count] = parseNumber({tokenStart, size_t(q - tokenStart)}, loc, count == 2);
            ++count;
            while (q < lineEnd && isBlank(*q)) ++q;
        }
        if (count < 3)
            throw InputError({file, line, int(q - lineStart) + 1},
                             fmt::format("{} value{} where a line needs three: easting, northing, height", count,
                                         count == 1 ? "" : "s"));
        if (!visit(XyzPoint{values[0], values[1], float(values[2]), line, xColumn})) return;
    }
}

// What the first pass learns: the extent, and the grid spacing as the smallest step between
// successive points along a row or column. Each point is checked against the grid of the
// points before it once that step has been seen twice, so that a file switching to another
// spacing or a shifted grid halfway is an error at the first point that does not fit.
class GridScan {
  public:
    explicit GridScan(std::string file) : file_(std::move(file)) {}

    void add(const XyzPoint &p) {
        if (count_++ == 0) {
            first_ = previous_ = p;
            minX_ = maxX_ = p.x;
            minY_ = maxY_ = p.y;
            return;
        }
        minX_ = std::min(minX_, p.x), maxX_ = std::max(maxX_, p.x);
        minY_ = std::min(minY_, p.y), maxY_ = std::max(maxY_, p.y);
        noteStep(p);
        if (stepCount_ >= 2) checkOnGrid(p);
        previous_ = p;
    }

    size_t count() const { return count_; }
    double spacing() const { return spacing_; }
    double minX() const { return minX_; }
    double maxX() const { return maxX_; }
    double minY() const { return minY_; }
    double maxY() const { return maxY_; }

  private:
    void noteStep(const XyzPoint &p) {
        double dx = std::abs(p.x - previous_.x), dy = std::abs(p.y - previous_.y);
        double step = dy <= 0.01 * dx ? dx : dx <= 0.01 * dy ? dy : 0;  // 0: a jump to another row
        if (step <= 0) return;
        if (step_ == 0 || step < (1 - kGridTolerance) * step_) {
            if (stepCount_ >= 2) throw offGrid(p);
            step_ = spacing_ = step;
            stepCount_ = 1;
            refinedX_ = refinedY_ = 1;
        } else if (std::abs(step - step_) <= kGridTolerance * step_) {
            ++stepCount_;
        }
    }

    // Also refines the spacing from the farthest point so far: files round coordinates, and
    // one rounded step would drift off the grid over thousands of nodes.
    void checkOnGrid(const XyzPoint &p) {
        for (auto [offset, refined] : {std::pair{p.x - first_.x, &refinedX_}, {p.y - first_.y, &refinedY_}}) {
            double nodes = offset / spacing_;
            double rounded = std::round(nodes);
            if (std::abs(nodes - rounded) > kGridTolerance) throw offGrid(p);
            if (std::abs(rounded) > *refined) {
                *refined = std::abs(rounded);
                spacing_ = std::abs(offset) / *refined;
            }
        }
    }

    InputError offGrid(const XyzPoint &p) const {
        return InputError({file_, p.line, p.column},
                          fmt::format("the point ({:.3f}, {:.3f}) is off the {:.6g} m grid of the points before it "
                                      "(mixed grid spacings or shifted tiles?)",
                                      p.x, p.y, spacing_));
    }

    std::string file_;
    size_t count_ = 0;
    XyzPoint first_, previous_;
    double minX_ = 0, maxX_ = 0, minY_ = 0, maxY_ = 0;
    double step_ = 0, spacing_ = 0;
    int stepCount_ = 0;
    double refinedX_ = 1, refinedY_ = 1;  // the node counts the spacing was last refined over
};

// An XYZ DGM lists its nodes: a grid may have gaps (water, removed buildings), but not more
// than a hundred nodes for each point given.
constexpr double kMaxXyzNodesPerPoint = 100;

HeightGrid emptyGridOver(const GridScan &scan, const std::string &file) {
    if (scan.count() < 2 || scan.spacing() <= 0)
        throw InputError({file, 0, 0}, "fewer than two points a grid step apart along a row or column");
    double columns = std::round((scan.maxX() - scan.minX()) / scan.spacing()) + 1;
    double rows = std::round((scan.maxY() - scan.minY()) / scan.spacing()) + 1;
    if (columns * rows > kMaxGridNodes)
        throw InputError({file, 0, 0},
                         fmt::format("the points span {} × {} nodes of {:.6g} m, more than the {:.0e} "
                                     "a DGM may have",
                                     columns, rows, scan.spacing(), kMaxGridNodes));
    // Checked before the grid is allocated: three points a kilometre apart on a 1 m grid
    // would otherwise ask for a million empty nodes per point.
    if (columns * rows > kMaxXyzNodesPerPoint * double(scan.count()))
        throw InputError({file, 0, 0},
                         fmt::format("the {} points span {} × {} nodes of {:.6g} m: they cover less than 1 % of "
                                     "their grid, which is no DGM (a point far off the others?)",
                                     scan.count(), columns, rows, scan.spacing()));
    HeightGrid grid;
    grid.west = scan.minX();
    grid.south = scan.minY();
    grid.columns = int(columns);
    grid.rows = int(rows);
    // Over the whole extent, so that the rounding of single coordinates averages out.
    grid.spacing = (scan.maxX() - scan.minX() + scan.maxY() - scan.minY()) / (columns - 1 + rows - 1);
    grid.heights.assign(size_t(grid.columns) * size_t(grid.rows), std::numeric_limits<float>::quiet_NaN());
    return grid;
}

// The node a point lies on, or -1 when it is off the grid.
int64_t nodeIndexOf(const HeightGrid &grid, const XyzPoint &p) {
    double column = (p.x - grid.west) / grid.spacing, row = (p.y - grid.south) / grid.spacing;
    double c = std::round(column), r = std::round(row);
    if (std::abs(column - c) > kGridTolerance || std::abs(row - r) > kGridTolerance) return -1;
    return int64_t(r) * grid.columns + int64_t(c);
}

XyzPoint firstPointAt(std::string_view text, const std::string &file, const HeightGrid &grid, int64_t node) {
    XyzPoint found;
    forEachPoint(text, file, [&](const XyzPoint &p) {
        if (nodeIndexOf(grid, p) != node) return true;
        found = p;
        return false;
    });
    return found;
}

}  // namespace

bool looksLikeXyz(const std::filesystem::path &file) {
    // The first lines only, and only so much of them: a binary raster has no line ends.
    std::ifstream in(file, std::ios::binary);
    std::string head(64 * 1024, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(in.gcount()));
    std::istringstream lines(head);
    std::string line;
    for (int i = 0; i < 100 && std::getline(lines, line); ++i) {
        size_t start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos) continue;
        if (line[start] == '#') continue;
        try {
            bool three = false;
            forEachPoint(line, file.string(), [&](const XyzPoint &) { return three = true, false; });
            return three;
        } catch (const InputError &) {
            return false;
        }
    }
    return false;
}

HeightGrid readXyzGrid(const std::filesystem::path &path) {
    std::string file = path.string();
    std::string text = readInputFile(path);

    GridScan scan(file);
    forEachPoint(text, file, [&](const XyzPoint &p) { return scan.add(p), true; });

    HeightGrid grid = emptyGridOver(scan, file);
    forEachPoint(text, file, [&](const XyzPoint &p) {
        int64_t node = nodeIndexOf(grid, p);
        if (node < 0)
            throw InputError({file, p.line, p.column},
                             fmt::format("the point ({:.3f}, {:.3f}) is off the {:.6g} m grid of the other points", p.x,
                                         p.y, grid.spacing));
        float &height = grid.heights[size_t(node)];
        if (height == p.height) return true;
        if (!std::isnan(height)) {
            XyzPoint earlier = firstPointAt(text, file, grid, node);
            throw InputError({file, p.line, p.column},
                             fmt::format("the point ({:.3f}, {:.3f}) has the height {} here but {} on line {}", p.x,
                                         p.y, p.height, earlier.height, earlier.line));
        }
        height = p.height;
        return true;
    });
    return grid;
}

}  // namespace veduta
