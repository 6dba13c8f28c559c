#include "geo/element_chaining.h"

#include <map>
#include <set>
#include <utility>

namespace veduta {

namespace {

using Key = std::pair<double, double>;

Key key(const MapPoint &p) { return {p.easting, p.northing}; }

// The elements meeting at each end point, in element order, and which are used.
class ElementGraph {
  public:
    explicit ElementGraph(const std::vector<MapLine> &elements) : elements_(elements), used_(elements.size(), false) {
        for (size_t i = 0; i < elements.size(); ++i) {
            if (elements[i].size() < 2) {
                used_[i] = true;
                continue;
            }
            ++unused_;
            for (const MapPoint *end : {&elements[i].front(), &elements[i].back()}) {
                Node &node = nodes_[key(*end)];
                node.elements.push_back(i);
                node.degree ^= 1;
            }
        }
        for (const auto &[k, node] : nodes_)
            if (node.degree) odd_.insert(k);
    }

    size_t unused() const { return unused_; }
    const std::set<Key> &oddPoints() const { return odd_; }

    // The first unused element meeting `at`, or elements.size().
    size_t nextAt(const MapPoint &at) {
        auto it = nodes_.find(key(at));
        if (it == nodes_.end()) return elements_.size();
        Node &node = it->second;
        while (node.cursor < node.elements.size() && used_[node.elements[node.cursor]]) ++node.cursor;
        return node.cursor < node.elements.size() ? node.elements[node.cursor] : elements_.size();
    }

    size_t firstUnused() {
        while (first_ < elements_.size() && used_[first_]) ++first_;
        return first_;
    }

    void use(size_t i) {
        used_[i] = true;
        --unused_;
        for (const MapPoint *end : {&elements_[i].front(), &elements_[i].back()}) {
            Key k = key(*end);
            if (odd_.erase(k) == 0) odd_.insert(k);
        }
    }

    // Appends element i to `points` going on from `points.back()`, reversed when it ends there.
    void append(size_t i, std::vector<MapPoint> &points) {
        const MapLine &e = elements_[i];
        bool forward = e.front() == points.back();
        use(i);
        if (forward) {
            for (size_t k = 1; k < e.size(); ++k) push(points, e[k]);
        } else {
            for (size_t k = e.size() - 1; k-- > 0;) push(points, e[k]);
        }
    }

    void start(size_t i, bool reversed, std::vector<MapPoint> &points) {
        const MapLine &e = elements_[i];
        use(i);
        if (!reversed) {
            for (const MapPoint &p : e) push(points, p);
        } else {
            for (size_t k = e.size(); k-- > 0;) push(points, e[k]);
        }
    }

  private:
    struct Node {
        std::vector<size_t> elements;
        size_t cursor = 0;
        int degree = 0;  // parity of the element ends here
    };

    static void push(std::vector<MapPoint> &points, const MapPoint &p) {
        if (points.empty() || !(points.back() == p)) points.push_back(p);
    }

    const std::vector<MapLine> &elements_;
    std::vector<bool> used_;
    std::map<Key, Node> nodes_;
    std::set<Key> odd_;
    size_t unused_ = 0;
    size_t first_ = 0;
};

}  // namespace

RingChaining chainRings(const std::vector<MapLine> &elements) {
    RingChaining result;
    ElementGraph graph(elements);
    while (graph.unused() > 0) {
        size_t i = graph.firstUnused();
        const MapPoint first = elements[i].front();
        std::vector<MapPoint> ring;
        graph.start(i, false, ring);
        size_t walked = 1;
        while (!(ring.back() == first)) {
            size_t next = graph.nextAt(ring.back());
            if (next == elements.size()) {
                result.closed = false;
                result.openEnd = ring.back();
                result.unusedElements = graph.unused() + walked;
                return result;
            }
            graph.append(next, ring);
            ++walked;
        }
        ring.pop_back();
        if (ring.size() >= 3) result.rings.push_back(std::move(ring));
    }
    return result;
}

std::vector<MapLine> chainLines(const std::vector<MapLine> &elements) {
    std::vector<MapLine> lines;
    ElementGraph graph(elements);
    while (graph.unused() > 0) {
        MapLine line;
        if (!graph.oddPoints().empty()) {
            const Key &k = *graph.oddPoints().begin();
            MapPoint loose{k.first, k.second};
            size_t i = graph.nextAt(loose);
            graph.start(i, !(elements[i].front() == loose), line);
        } else {
            graph.start(graph.firstUnused(), false, line);
        }
        for (size_t next = graph.nextAt(line.back()); next < elements.size(); next = graph.nextAt(line.back()))
            graph.append(next, line);
        if (line.size() >= 2) lines.push_back(std::move(line));
    }
    return lines;
}

}  // namespace veduta
