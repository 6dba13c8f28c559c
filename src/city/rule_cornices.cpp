#include "city/rule_cornices.h"

#include <algorithm>
#include <cmath>

namespace veduta {
namespace {

// Places of one <Cornice> in one material at one height.
struct CorniceBand {
    const CorniceRule *rule = nullptr;
    MaterialId material = kNoMaterial;
    double bottom = 0, top = 0;
    std::vector<const CornicePlace *> places;

    bool takes(const CornicePlace &p) const {
        return p.rule == rule && p.material == material && std::abs(p.bottom - bottom) <= kCorniceJoinTolerance &&
            std::abs(p.top - top) <= kCorniceJoinTolerance;
    }
};

// A stretch of one facade that the band covers without a gap.
struct Stretch {
    size_t facade = 0;
    double left = 0, right = 0;
};

std::vector<CorniceBand> bandsOf(const std::vector<CornicePlace> &places) {
    std::vector<CorniceBand> bands;
    for (const CornicePlace &p : places) {
        auto band = std::find_if(bands.begin(), bands.end(), [&](const CorniceBand &b) { return b.takes(p); });
        if (band == bands.end()) band = bands.insert(bands.end(), {p.rule, p.material, p.bottom, p.top, {}});
        band->places.push_back(&p);
    }
    return bands;
}

std::vector<Stretch> stretchesOf(const CorniceBand &band) {
    std::vector<const CornicePlace *> places = band.places;
    std::sort(places.begin(), places.end(), [](const CornicePlace *a, const CornicePlace *b) {
        return a->facade != b->facade ? a->facade < b->facade : a->left < b->left;
    });
    std::vector<Stretch> stretches;
    for (const CornicePlace *p : places) {
        if (!stretches.empty() && stretches.back().facade == p->facade &&
            p->left <= stretches.back().right + kCorniceJoinTolerance)
            stretches.back().right = std::max(stretches.back().right, p->right);
        else stretches.push_back({p->facade, p->left, p->right});
    }
    return stretches;
}

Vec2d planPoint(const StartShape &facade, double along) {
    Vec3f p = facade.facadeToWorld.applyPoint({float(along), 0.0f, 0.0f});
    return {p.x, p.y};
}

Vec2d planDirection(const StartShape &facade) {
    Vec3f d = facade.facadeToWorld.applyVector({1.0f, 0.0f, 0.0f});
    Vec2d plan{d.x, d.y};
    return plan * (1 / length(plan));
}

// For each stretch, the stretch that continues it round the next corner, or -1.
std::vector<int> continuations(const std::vector<Stretch> &stretches, const std::vector<StartShape> &facades) {
    std::vector<int> next(stretches.size(), -1);
    std::vector<bool> continued(stretches.size(), false);
    const double sharpest = std::cos(kSweepTurnLimit * M_PI / 180);
    for (size_t i = 0; i < stretches.size(); ++i) {
        const StartShape &from = facades[stretches[i].facade];
        if (stretches[i].right < from.width - kCorniceJoinTolerance) continue;
        Vec2d corner = planPoint(from, from.width);
        for (size_t j = 0; j < stretches.size(); ++j) {
            const StartShape &to = facades[stretches[j].facade];
            if (continued[j] || stretches[j].facade == stretches[i].facade ||
                stretches[j].left > kCorniceJoinTolerance ||
                length(planPoint(to, 0) - corner) > kCorniceJoinTolerance ||
                dot(planDirection(from), planDirection(to)) < sharpest)
                continue;
            next[i] = int(j);
            continued[j] = true;
            break;
        }
    }
    return next;
}

// The chains of stretches that the continuations make: open ones from their first stretch, then
// the rings that remain.
std::vector<std::pair<std::vector<size_t>, bool>> chainsOf(const std::vector<int> &next) {
    std::vector<bool> hasPrevious(next.size(), false), used(next.size(), false);
    for (int n : next)
        if (n >= 0) hasPrevious[size_t(n)] = true;
    std::vector<std::pair<std::vector<size_t>, bool>> chains;
    auto follow = [&](size_t first, bool ring) {
        std::vector<size_t> chain;
        for (int s = int(first); s >= 0 && !used[size_t(s)]; s = next[size_t(s)]) {
            used[size_t(s)] = true;
            chain.push_back(size_t(s));
        }
        chains.push_back({std::move(chain), ring});
    };
    for (size_t s = 0; s < next.size(); ++s)
        if (!hasPrevious[s]) follow(s, false);
    for (size_t s = 0; s < next.size(); ++s)
        if (!used[s]) follow(s, true);
    return chains;
}

void sweepChain(const CorniceBand &band, const std::vector<Stretch> &stretches, const std::vector<size_t> &chain,
                bool ring, const std::vector<StartShape> &facades, CorniceRun &out) {
    const StartShape &first = facades[stretches[chain.front()].facade];
    std::vector<Vec2d> points;
    for (size_t s : chain) {
        const Stretch &stretch = stretches[s];
        if (stretch.right - stretch.left <= kCorniceJoinTolerance) continue;
        points.push_back(planPoint(facades[stretch.facade], stretch.left));
        points.push_back(planPoint(facades[stretch.facade], stretch.right));
    }
    Vec3f out3 = first.facadeToWorld.applyVector({0.0f, 0.0f, 1.0f});
    Vec2d direction = planDirection(first);
    OutwardSide outward = direction.y * out3.x - direction.x * out3.y >= 0 ? OutwardSide::Right : OutwardSide::Left;
    double base = first.facadeToWorld.applyPoint({0.0f, float(band.bottom), 0.0f}).z;
    SweepPath path = sweepPathThrough(points, base, ring, outward);
    if (path.points.size() < (path.closed ? 3u : 2u)) return;
    CorniceRun run = buildCorniceRun(*band.rule->cornice, path, band.top - band.bottom, band.material);
    out.mesh.append(run.mesh, Transform());
    for (ConsoleSet &set : run.consoles) {
        set.objectFile = (band.rule->directory / set.objectFile).string();
        out.consoles.push_back(std::move(set));
    }
}

}  // namespace

CorniceRun sweepRuleCornices(const std::vector<CornicePlace> &places, const std::vector<StartShape> &facades) {
    CorniceRun swept;
    for (const CorniceBand &band : bandsOf(places)) {
        std::vector<Stretch> stretches = stretchesOf(band);
        for (auto &[chain, ring] : chainsOf(continuations(stretches, facades)))
            sweepChain(band, stretches, chain, ring, facades, swept);
    }
    return swept;
}

}  // namespace veduta
