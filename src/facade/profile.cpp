#include "facade/profile.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/check.h"

namespace veduta {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
// Below this a start tangent counts as square to the heading (an arc's sense, see profile.h).
constexpr double kSquareTolerance = 1e-9;
// A step must move the turtle by more than this part of the profile's largest coordinate (in x or
// y): scaledOutline's shift and scale round each coordinate by about 1e-16 of that, and a step
// lost in the rounding would leave two equal points, a segment without a direction.
constexpr double kLeastStep = 1e-12;

// `v` turned by `degrees` toward its normal, i.e. clockwise in the (out, up) plane.
Vec2d turned(Vec2d v, double degrees) {
    double c = std::cos(degrees * kDegree), s = std::sin(degrees * kDegree);
    return {v.x * c + v.y * s, -v.x * s + v.y * c};
}

Vec2d normalOf(Vec2d heading) { return turned(heading, 90); }

int textureIndex(const DescriptionItem &item, size_t index) {
    double value = item.number(index, "a texture index");
    if (value != std::floor(value) || std::abs(value) > 1e6)
        throw InputError(item.fields[index].loc,
                         fmt::format("a texture index must be a whole number, found {}", item.fields[index].text));
    return int(value);
}

double positive(const DescriptionItem &item, size_t index, std::string_view what) {
    double value = item.number(index, what);
    if (value <= 0) throw InputError(item.fields[index].loc, fmt::format("{} must be positive, found {}", what, value));
    return value;
}

// A positive length in the profile's units, up to kProfileSizeLimit.
double size(const DescriptionItem &item, size_t index, std::string_view what) {
    double value = positive(item, index, what);
    if (value > kProfileSizeLimit)
        throw InputError(item.fields[index].loc,
                         fmt::format("{} must be at most {}, found {}", what, kProfileSizeLimit, value));
    return value;
}

ProfileCommand command(const DescriptionItem &item) {
    ProfileCommand result;
    result.loc = item.loc;
    const std::string &name = item.word(0, "a command (line or arc)");
    if (name == "line") {
        result.kind = ProfileCommand::Kind::Line;
    } else if (name == "arc") {
        result.kind = ProfileCommand::Kind::Arc;
    } else {
        throw InputError(item.fields[0].loc, fmt::format("unknown command '{}' (line or arc)", name));
    }
    bool arc = result.kind == ProfileCommand::Kind::Arc;
    size_t plain = arc ? 5 : 4;
    if (item.fields.size() != plain && item.fields.size() != plain + 3)
        throw InputError(item.loc,
                         fmt::format("{} takes {} fields, or {} with three texture indices; found {}", name, plain,
                                     plain + 3, item.fields.size()));
    const std::string &basis = item.word(1, "rel or abs");
    if (basis != "rel" && basis != "abs")
        throw InputError(item.fields[1].loc, fmt::format("expected rel or abs, found '{}'", basis));
    result.absolute = basis == "abs";
    result.angle = item.number(2, "an angle");
    if (std::abs(result.angle) > kProfileAngleLimit)
        throw InputError(item.fields[2].loc,
                         fmt::format("an angle must lie in [-{0}, {0}], found {1}", kProfileAngleLimit, result.angle));
    if (arc) {
        result.arcAngle = item.number(3, "the arc's angle");
        if (result.arcAngle == 0 || std::abs(result.arcAngle) > 360)
            throw InputError(item.fields[3].loc,
                             fmt::format("an arc's angle must be in [-360, 0) or (0, 360], found {}", result.arcAngle));
    }
    result.size = size(item, plain - 1, arc ? "the radius" : "the length");
    if (item.fields.size() == plain + 3)
        for (size_t i = 0; i < 3; ++i) result.textures[i] = textureIndex(item, plain + i);
    return result;
}

double unitCoordinate(const DescriptionItem &item, size_t index, std::string_view what) {
    double value = item.number(index, what);
    if (value < 0 || value > 1)
        throw InputError(item.fields[index].loc, fmt::format("{} must lie in [0, 1], found {}", what, value));
    return value;
}

TextureRegion textureRegion(const DescriptionItem &item) {
    item.expectFieldCount(5, 5, "a texture (\"file\", left, top, right, bottom)");
    TextureRegion region;
    region.loc = item.loc;
    region.file = item.string(0, "the texture's file");
    region.left = unitCoordinate(item, 1, "left");
    double top = unitCoordinate(item, 2, "top");
    region.right = unitCoordinate(item, 3, "right");
    double bottom = unitCoordinate(item, 4, "bottom");
    if (region.right <= region.left)
        throw InputError(item.fields[3].loc, "a texture's right must lie right of its left");
    // The thesis counts v upward (Fig. 5.28); see profile.h.
    if (top <= bottom) throw InputError(item.fields[2].loc, "a texture's top must lie above its bottom (v counts up)");
    region.top = 1 - top;
    region.bottom = 1 - bottom;
    // 1 - 1e-300 is 1: a rectangle that was not empty counted up may be empty counted down, and
    // a frieze piece would be infinitely wide to keep its aspect.
    if (region.bottom <= region.top)
        throw InputError(item.fields[2].loc, "a texture's top and bottom are too close to tell apart");
    return region;
}

// The arc of `command` from `start` with the turtle heading `heading`: appends its points, returns
// the end heading.
Vec2d traceArc(const ProfileCommand &command, Vec2d heading, double arcStepDegrees, std::vector<Vec2d> &points) {
    Vec2d start = points.back();
    Vec2d basis = command.absolute ? Vec2d{0, 1} : heading;
    Vec2d toCentre = turned(normalOf(basis) * -1.0, command.angle);
    Vec2d centre = start + toCentre * command.size;
    Vec2d radial = toCentre * -1.0;
    Vec2d counterClockwiseTangent{-radial.y, radial.x};
    double along = dot(counterClockwiseTangent, heading);
    bool counterClockwise = std::abs(along) > kSquareTolerance
        ? along > 0
        : (dot(counterClockwiseTangent, normalOf(heading)) > 0) == (command.arcAngle > 0);
    // Clockwise is the sense of turned(); counter-clockwise sweeps turn by negative degrees.
    double sweep = counterClockwise ? -std::abs(command.arcAngle) : std::abs(command.arcAngle);
    int steps = std::max(1, int(std::ceil(std::abs(sweep) / arcStepDegrees - 1e-9)));
    for (int i = 1; i <= steps; ++i) points.push_back(centre + turned(radial, sweep * i / steps) * command.size);
    Vec2d endRadial = turned(radial, sweep);
    return counterClockwise ? Vec2d{-endRadial.y, endRadial.x} : Vec2d{endRadial.y, -endRadial.x};
}

}  // namespace

Profile parseProfile(const DescriptionBlock &block) {
    Profile profile;
    profile.loc = block.loc;
    if (block.items.empty()) throw InputError(block.loc, "a profile needs at least one line or arc");
    if (block.items.size() > kProfileCommandLimit)
        throw InputError(block.items[kProfileCommandLimit].loc,
                         fmt::format("a profile may have at most {} commands", kProfileCommandLimit));
    for (const DescriptionItem &item : block.items) profile.commands.push_back(command(item));
    return profile;
}

std::vector<Console> parseConsoles(const DescriptionBlock &block) {
    if (block.items.empty()) throw InputError(block.loc, "a Consoles block needs at least one console");
    if (block.items.size() % 2 != 0)
        throw InputError(block.items.back().loc, "a console is two items: abstand; \"obj\", breite, hoehe;");
    std::vector<Console> consoles;
    for (size_t i = 0; i < block.items.size(); i += 2) {
        const DescriptionItem &spacing = block.items[i], &shape = block.items[i + 1];
        spacing.expectFieldCount(1, 1, "a console's spacing (abstand)");
        shape.expectFieldCount(3, 3, "a console (\"obj\", breite, hoehe)");
        Console console;
        console.loc = spacing.loc;
        console.spacing = positive(spacing, 0, "the spacing");
        console.objectFile = shape.string(0, "the console's object file");
        console.width = size(shape, 1, "the width");
        console.height = size(shape, 2, "the height");
        consoles.push_back(console);
    }
    return consoles;
}

std::vector<TextureRegion> parseTexturePool(const DescriptionBlock &block) {
    if (block.items.empty()) throw InputError(block.loc, "a texture pool needs at least one texture");
    std::vector<TextureRegion> pool;
    for (const DescriptionItem &item : block.items) pool.push_back(textureRegion(item));
    return pool;
}

CorniceDescription parseCorniceDescription(std::string_view text, const std::string &file) {
    CorniceDescription description;
    const DescriptionBlock *profile = nullptr, *consoles = nullptr, *textures = nullptr;
    std::vector<DescriptionBlock> blocks = readDescriptionBlocks(text, file);
    for (const DescriptionBlock &block : blocks) {
        const DescriptionBlock **slot = nullptr;
        if (block.name == "Modifications") slot = &profile;
        else if (block.name == "Consoles") slot = &consoles;
        else if (block.name == "TexturePool" || block.name == "TextureDescs") slot = &textures;
        else
            throw InputError(
                block.loc,
                fmt::format("unknown block '{}' (Modifications, Consoles, TexturePool or TextureDescs)", block.name));
        if (*slot)
            throw InputError(
                block.loc, fmt::format("a second {} block (the first is at {})", block.name, (*slot)->loc.toString()));
        *slot = &block;
    }
    if (!profile) throw InputError(FileLoc{file, 1, 1}, "the cornice has no Modifications block");
    description.profile = parseProfile(*profile);
    if (consoles) description.consoles = parseConsoles(*consoles);
    if (textures) description.textures = parseTexturePool(*textures);
    for (const ProfileCommand &command : description.profile.commands)
        for (int index : command.textures)
            if (index >= int(description.textures.size()))
                throw InputError(command.loc,
                                 fmt::format("texture index {} names no texture (the pool has {})", index,
                                             description.textures.size()));
    return description;
}

ProfileOutline traceProfile(const Profile &profile, double arcStepDegrees) {
    VEDUTA_CHECK(arcStepDegrees > 0 && arcStepDegrees <= 90, "an arc step is a positive angle up to 90°");
    ProfileOutline outline;
    outline.points.push_back({0, 0});
    Vec2d heading{0, 1};
    for (const ProfileCommand &command : profile.commands) {
        if (command.kind == ProfileCommand::Kind::Line) {
            heading = turned(command.absolute ? Vec2d{0, 1} : heading, command.angle);
            outline.points.push_back(outline.points.back() + heading * command.size);
        } else {
            heading = traceArc(command, heading, arcStepDegrees, outline.points);
        }
        outline.commandEnds.push_back(outline.points.size() - 1);
    }
    double largest = 0;
    for (Vec2d point : outline.points) largest = std::max({largest, std::abs(point.x), std::abs(point.y)});
    size_t first = 0;
    for (size_t c = 0; c < profile.commands.size(); ++c) {
        for (size_t i = first + 1; i <= outline.commandEnds[c]; ++i) {
            Vec2d step = outline.points[i] - outline.points[i - 1];
            if (std::max(std::abs(step.x), std::abs(step.y)) <= kLeastStep * largest)
                throw InputError(
                    profile.commands[c].loc,
                    fmt::format("this command is too short to draw in a profile reaching {} units from its start",
                                largest));
        }
        first = outline.commandEnds[c];
    }
    return outline;
}

double heightScale(const Profile &profile, const ProfileOutline &outline, double height) {
    // parseProfile's limits keep a traced outline finite; this guards outlines from elsewhere.
    for (Vec2d point : outline.points)
        if (!std::isfinite(point.x) || !std::isfinite(point.y))
            throw InputError(profile.loc, "the profile reaches past any finite coordinate");
    auto [lowest, highest] =
        std::minmax_element(outline.points.begin(), outline.points.end(), [](Vec2d a, Vec2d b) { return a.y < b.y; });
    double extent = highest->y - lowest->y;
    auto [left, right] =
        std::minmax_element(outline.points.begin(), outline.points.end(), [](Vec2d a, Vec2d b) { return a.x < b.x; });
    double width = right->x - left->x;
    if (!std::isfinite(extent) || !std::isfinite(width))
        throw InputError(profile.loc, "the profile reaches past any finite coordinate");
    if (extent <= 1e-12 * std::max(1.0, std::abs(highest->y)))
        throw InputError(profile.loc, "the profile has no height to fill a partition with");
    if (width > kProfileAspectLimit * extent)
        throw InputError(profile.loc,
                         fmt::format("the profile is more than {} times as wide as it is high", kProfileAspectLimit));
    return height / extent;
}

ProfileOutline scaledOutline(const ProfileOutline &outline, double scale) {
    double lowest =
        std::min_element(outline.points.begin(), outline.points.end(), [](Vec2d a, Vec2d b) { return a.y < b.y; })->y;
    ProfileOutline result = outline;
    for (Vec2d &point : result.points) point = Vec2d{point.x, point.y - lowest} * scale;
    return result;
}

}  // namespace veduta
