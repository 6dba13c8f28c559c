#include "compare/compare_report.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "core/json_text.h"
#include "core/xml_escape.h"
#include "io/output_files.h"

namespace veduta {

namespace {

// ---- JSON -------------------------------------------------------------------------------

std::string jsonNumber(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : "null"; }
std::string jsonNumber(const std::optional<double> &v) { return v ? jsonNumber(*v) : "null"; }

std::string costJson(const SceneCost &c) {
    return fmt::format(
        "{{\"scene\": {}, \"buildings\": {}, \"triangles_stored\": {}, \"triangles_effective\": {}, "
        "\"instances\": {}, \"bvh_bytes\": {}, \"generate_seconds\": {}, \"bvh_seconds\": {}, "
        "\"render_seconds\": {}, \"preview_seconds\": {}, \"peak_memory_bytes\": {}, \"samples_per_pixel\": {}, "
        "\"effort\": {{\"rule_lines\": {}, \"parameters\": {}, \"surfaces\": {}, \"vertices\": {}}}}}",
        jsonString(c.name), c.buildings, c.storedTriangles, c.effectiveTriangles, c.instances, c.bvhBytes,
        jsonNumber(c.generateSeconds), jsonNumber(c.bvhSeconds), jsonNumber(c.renderSeconds),
        jsonNumber(c.previewSeconds), c.peakMemoryBytes, c.samplesPerPixel, c.effort.ruleLines, c.effort.parameters,
        c.effort.surfaces, c.effort.vertices);
}

std::string metricsJson(const ImageMetrics &m) {
    return fmt::format("{{\"relmse\": {}, \"psnr\": {}, \"ssim\": {}}}", jsonNumber(m.relMse), jsonNumber(m.psnr),
                       jsonNumber(m.ssim));
}

std::string vecJson(const Vec3f &v) {
    return fmt::format("[{}, {}, {}]", jsonNumber(v.x), jsonNumber(v.y), jsonNumber(v.z));
}

std::string recordJson(const std::optional<MeasuredBuilding> &m) {
    if (!m) return "null";
    std::string record = "null";
    if (m->record)
        record =
            fmt::format("{{\"base\": {}, \"eaves\": {}, \"ridge\": {}, \"roof\": {}}}", jsonNumber(m->record->base),
                        jsonNumber(m->record->eaves), jsonNumber(m->record->ridge), jsonString(m->record->roof));
    return fmt::format("{{\"id\": {}, \"footprint_area\": {}, \"volume\": {}, \"record\": {}}}", m->id,
                       jsonNumber(m->footprintArea), jsonNumber(m->volume), record);
}

// ---- images -----------------------------------------------------------------------------

const char kBase64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64(const std::vector<unsigned char> &bytes) {
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t n = uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) n |= uint32_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) n |= bytes[i + 2];
        out += kBase64[n >> 18 & 63];
        out += kBase64[n >> 12 & 63];
        out += i + 1 < bytes.size() ? kBase64[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? kBase64[n & 63] : '=';
    }
    return out;
}

std::string dataUri(const std::vector<uint8_t> &pixels, int width, int height, int channels) {
    return "data:image/png;base64," + base64(encodePng(pixels, width, height, channels));
}

std::string dataUri(const RgbaImage &image) { return dataUri(srgbPixels(image), image.width(), image.height(), 4); }

// |A − B| of the display images' luma as 8-bit RGB, brighter where they differ more (×4,
// black → red → yellow).
std::string differenceUri(const RgbaImage &a, const RgbaImage &b) {
    std::vector<float> la = displayLuma(a), lb = displayLuma(b);
    std::vector<uint8_t> pixels(la.size() * 3, 0);
    for (size_t i = 0; i < la.size(); ++i) {
        float d = std::min(1.0f, 4 * std::abs(la[i] - lb[i]));
        pixels[3 * i] = uint8_t(std::lround(255 * std::min(1.0f, 2 * d)));
        pixels[3 * i + 1] = uint8_t(std::lround(255 * std::max(0.0f, 2 * d - 1)));
    }
    return dataUri(pixels, a.width(), a.height(), 3);
}

Vec3f iouColour(double iou) {
    auto t = float(std::clamp(iou, 0.0, 1.0));
    Vec3f red{0.8f, 0.05f, 0.03f}, yellow{0.9f, 0.75f, 0.05f}, green{0.05f, 0.45f, 0.1f};
    return t < 0.5f ? red + (yellow - red) * (2 * t) : yellow + (green - yellow) * (2 * t - 1);
}

// ---- HTML -------------------------------------------------------------------------------

std::string figure(const std::optional<double> &v, const char *format) {
    return v && std::isfinite(*v) ? fmt::format(fmt::runtime(format), *v) : "–";
}

const char kStyle[] = R"(
body { font: 14px/1.45 system-ui, sans-serif; margin: 2em auto; max-width: 1500px; padding: 0 1em; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 2em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.5em 0; } td, th { padding: 2px 10px; border-bottom: 1px solid #eee; text-align: right; }
th:first-child, td:first-child { text-align: left; }
.pair { display: flex; gap: 8px; flex-wrap: wrap; } .pair figure { margin: 0; flex: 0 1 480px; } .pair img { width: 100%; }
figcaption { font-size: 0.9em; color: #555; }
.slider { position: relative; max-width: 960px; } .slider img { display: block; width: 100%; }
.slider .top { position: absolute; top: 0; left: 0; width: 100%; clip-path: inset(0 50% 0 0); }
.slider input { width: 100%; }
)";

// An A/B slider: B over A, clipped to the right of the handle; and a flicker button.
const char kScript[] = R"(
for (const s of document.querySelectorAll('.slider')) {
  const top = s.querySelector('.top'), range = s.querySelector('input[type=range]');
  range.addEventListener('input', () => { top.style.clipPath = `inset(0 ${100 - range.value}% 0 0)`; });
  const button = s.querySelector('button'); let timer = null;
  button.addEventListener('click', () => {
    if (timer) { clearInterval(timer); timer = null; top.style.visibility = 'visible'; return; }
    timer = setInterval(() => { top.style.visibility = top.style.visibility === 'hidden' ? 'visible' : 'hidden'; }, 500);
  });
}
// Says in the title whether every picture loaded (tests/app/compare_report_chromium_test.sh reads it).
const images = [...document.images];
Promise.all(images.map(i => i.complete ? Promise.resolve() : new Promise(r => { i.onload = r; i.onerror = r; })))
  .then(() => {
    const failed = images.filter(i => !i.naturalWidth).length;
    document.title = `veduta compare: ${images.length - failed} images loaded, ${failed} failed`;
  });
)";

std::string costRows(const SceneCost &a, const SceneCost &b) {
    std::string rows;
    auto row = [&](const char *name, const std::string &va, const std::string &vb) {
        rows += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td></tr>\n", name, va, vb);
    };
    auto count = [](uint64_t n) { return fmt::format("{}", n); };
    auto seconds = [](double s) { return fmt::format("{:.2f} s", s); };
    auto mib = [](int64_t bytes) { return fmt::format("{:.1f} MiB", double(bytes) / (1 << 20)); };
    row("buildings", count(a.buildings), count(b.buildings));
    row("triangles stored", count(a.storedTriangles), count(b.storedTriangles));
    row("triangles effective", count(a.effectiveTriangles), count(b.effectiveTriangles));
    row("instances", count(a.instances), count(b.instances));
    row("BVH", mib(a.bvhBytes), mib(b.bvhBytes));
    row("generation", seconds(a.generateSeconds), seconds(b.generateSeconds));
    row("BVH build", seconds(a.bvhSeconds), seconds(b.bvhSeconds));
    row(fmt::format("path tracing ({} spp, all views)", a.samplesPerPixel).c_str(), seconds(a.renderSeconds),
        seconds(b.renderSeconds));
    row("preview (all views)", seconds(a.previewSeconds), seconds(b.previewSeconds));
    row("peak memory of the process, after the scene", mib(a.peakMemoryBytes), mib(b.peakMemoryBytes));
    row("rule-file lines", count(a.effort.ruleLines), count(b.effort.ruleLines));
    row("parameters in the scene", count(a.effort.parameters), count(b.effort.parameters));
    row("modelled surfaces", count(a.effort.surfaces), count(b.effort.surfaces));
    row("modelled vertices", count(a.effort.vertices), count(b.effort.vertices));
    return rows;
}

std::string viewSection(const ViewResult &v, size_t index, const CompareReport &r) {
    std::string a = dataUri(v.renderA), b = dataUri(v.renderB);
    return fmt::format(
        R"(<h2 id="view{0}">View {0}: {1}</h2>
<p>camera at {2:.1f} {3:.1f} {4:.1f}, looking at {5:.1f} {6:.1f} {7:.1f}, {8}×{9}, {10}° field of view</p>
<table><tr><th></th><th>relMSE</th><th>PSNR</th><th>SSIM</th></tr>
<tr><td>path-traced</td><td>{11:.4g}</td><td>{12:.2f} dB</td><td>{13:.4f}</td></tr>
<tr><td>preview</td><td>{14:.4g}</td><td>{15:.2f} dB</td><td>{16:.4f}</td></tr>
<tr><td>silhouette IoU (building pixels)</td><td colspan="3">{17:.4f}</td></tr></table>
<div class="pair"><figure><img alt="A, path-traced" src="{18}"><figcaption>A: {19}</figcaption></figure>
<figure><img alt="B, path-traced" src="{20}"><figcaption>B: {21}</figcaption></figure>
<figure><img alt="difference" src="{22}"><figcaption>|A − B| of the display images, ×4</figcaption></figure></div>
<div class="slider"><img alt="A" src="{18}"><img class="top" alt="B" src="{20}">
<input type="range" min="0" max="100" value="50" aria-label="A/B slider"> <button>flicker</button>
<figcaption>A on the right, B on the left of the slider</figcaption></div>
<div class="pair"><figure><img alt="A, preview" src="{23}"><figcaption>A, preview</figcaption></figure>
<figure><img alt="B, preview" src="{24}"><figcaption>B, preview</figcaption></figure></div>
)",
        index + 1, escapeXml(v.view.name), v.view.camera.position.x, v.view.camera.position.y, v.view.camera.position.z,
        v.view.camera.lookAt.x, v.view.camera.lookAt.y, v.view.camera.lookAt.z, v.view.camera.width,
        v.view.camera.height, v.view.camera.verticalFovDegrees, v.rendered.relMse, v.rendered.psnr, v.rendered.ssim,
        v.previewed.relMse, v.previewed.psnr, v.previewed.ssim, v.silhouetteIou, a, escapeXml(r.a.name), b,
        escapeXml(r.b.name), differenceUri(v.renderA, v.renderB), dataUri(v.previewA), dataUri(v.previewB));
}

// The buildings whose footprints agree least, at most `limit` of them.
std::string buildingRows(const BuildingComparison &c, size_t limit) {
    std::vector<const BuildingPair *> pairs;
    for (const BuildingPair &p : c.pairs) pairs.push_back(&p);
    std::stable_sort(pairs.begin(), pairs.end(),
                     [](const BuildingPair *x, const BuildingPair *y) { return x->footprintIou < y->footprintIou; });
    std::string rows;
    for (size_t i = 0; i < std::min(limit, pairs.size()); ++i) {
        const BuildingPair &p = *pairs[i];
        auto roof = [](const std::optional<MeasuredBuilding> &m) {
            return m && m->record && !m->record->roof.empty() ? m->record->roof : std::string("–");
        };
        rows += fmt::format(
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{:.3f}</td><td>{}</td><td>{}</td><td>{}</td>"
            "<td>{} / {}</td></tr>\n",
            p.a ? fmt::format("{}", p.a->id) : "–", p.b ? fmt::format("{}", p.b->id) : "–", p.matchedBy, p.footprintIou,
            figure(p.eavesError, "{:+.2f} m"), figure(p.ridgeError, "{:+.2f} m"),
            figure(p.volumeError ? std::optional<double>(*p.volumeError * 100) : std::nullopt, "{:+.1f} %"), roof(p.a),
            roof(p.b));
    }
    return rows;
}

}  // namespace

RgbaImage districtErrorMap(const CompareReport &report, int maxSide) {
    const GroundGrid &g = report.mapA.grid;
    std::map<uint32_t, Vec3f> colourA, colourB;
    const Vec3f unmatched{0.75f, 0.1f, 0.7f};
    for (const BuildingPair &p : report.buildings.pairs) {
        Vec3f c = p.a && p.b ? iouColour(p.footprintIou) : unmatched;
        if (p.a) colourA[p.a->id] = c;
        if (p.b) colourB[p.b->id] = c;
    }
    int side = std::max(g.width, g.height);
    int step = std::max(1, (side + maxSide - 1) / std::max(1, maxSide));
    int w = std::max(1, g.width / step), h = std::max(1, g.height / step);
    RgbaImage map(w, h);
    bool plans = report.buildings.groundPlans;
    const std::vector<uint32_t> &ownerA = plans ? report.mapA.plan : report.mapA.building;
    const std::vector<uint32_t> &ownerB = plans ? report.mapB.plan : report.mapB.building;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t cell = size_t(g.height - 1 - y * step) * size_t(g.width) + size_t(x * step);  // north up
            Vec3f c{0.93f, 0.93f, 0.9f};
            if (uint32_t id = ownerA[cell]) c = colourA[id];
            else if (uint32_t idB = ownerB[cell]) c = colourB[idB] * 0.8f;
            map.set(x, y, c);
        }
    return map;
}

std::string reportJson(const CompareReport &r) {
    const BuildingComparison &c = r.buildings;
    std::string views;
    for (const ViewResult &v : r.views)
        views += fmt::format(
            "{}\n    {{\"name\": {}, \"camera\": {{\"position\": {}, \"look_at\": {}, \"fov\": {}, "
            "\"resolution\": [{}, {}]}}, \"path_traced\": {}, \"preview\": {}, "
            "\"silhouette_iou\": {}}}",
            views.empty() ? "" : ",", jsonString(v.view.name), vecJson(v.view.camera.position),
            vecJson(v.view.camera.lookAt), jsonNumber(v.view.camera.verticalFovDegrees), v.view.camera.width,
            v.view.camera.height, metricsJson(v.rendered), metricsJson(v.previewed), jsonNumber(v.silhouetteIou));
    std::string buildings;
    for (const BuildingPair &p : c.pairs)
        buildings += fmt::format(
            "{}\n    {{\"a\": {}, \"b\": {}, \"matched_by\": {}, \"footprint_iou\": {}, \"eaves_error\": {}, "
            "\"ridge_error\": {}, \"volume_error\": {}, \"roof_agrees\": {}}}",
            buildings.empty() ? "" : ",", recordJson(p.a), recordJson(p.b), jsonString(p.matchedBy),
            jsonNumber(p.footprintIou), jsonNumber(p.eavesError), jsonNumber(p.ridgeError), jsonNumber(p.volumeError),
            p.roofAgrees ? (*p.roofAgrees ? "true" : "false") : "null");
    return fmt::format(
        "{{\n  \"a\": {},\n  \"b\": {},\n  \"summary\": {{\"matched_by_id\": {}, \"matched_by_overlap\": {}, "
        "\"only_a\": {}, \"only_b\": {}, \"mean_footprint_iou\": {}, \"mean_abs_eaves_error\": {}, "
        "\"mean_abs_ridge_error\": {}, \"mean_abs_volume_error\": {}, \"roof_agreement\": {}, \"grid_cell\": {}, "
        "\"footprints\": {}}},\n"
        "  \"views\": [{}\n  ],\n  \"buildings\": [{}\n  ]\n}}\n",
        costJson(r.a), costJson(r.b), c.matchedById, c.matchedByOverlap, c.onlyA, c.onlyB,
        jsonNumber(c.meanFootprintIou), jsonNumber(c.meanAbsEavesError), jsonNumber(c.meanAbsRidgeError),
        jsonNumber(c.meanAbsVolumeError), jsonNumber(c.roofAgreement), jsonNumber(r.mapA.grid.cell),
        jsonString(c.groundPlans ? "ground plans" : "seen from above"), views, buildings);
}

std::string reportHtml(const CompareReport &r) {
    const BuildingComparison &c = r.buildings;
    std::string sections;
    for (size_t i = 0; i < r.views.size(); ++i) sections += viewSection(r.views[i], i, r);
    return fmt::format(
        R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>veduta compare</title><style>{}</style></head>
<body>
<h1>veduta compare</h1>
<p><b>A</b> (the reference): {}<br><b>B</b>: {}</p>
<h2>Buildings</h2>
<table>
<tr><td>paired by id</td><td>{}</td></tr><tr><td>paired by overlap</td><td>{}</td></tr>
<tr><td>only in A</td><td>{}</td></tr><tr><td>only in B</td><td>{}</td></tr>
<tr><td>mean footprint IoU</td><td>{:.4f}</td></tr>
<tr><td>mean |eaves error|</td><td>{:.3f} m</td></tr><tr><td>mean |ridge error|</td><td>{:.3f} m</td></tr>
<tr><td>mean |volume error|</td><td>{:.2f} %</td></tr><tr><td>roof types agreeing</td><td>{:.1f} %</td></tr>
</table>
<p>Footprints and volumes are measured on a {:.2f} m grid, footprints as {}; volumes are what lies
over them under the topmost surface; heights and roof types are what the scenes' generators record.</p>
<figure><img alt="district map" src="{}"><figcaption>The district from above, north up: each building
coloured by its footprint IoU with its partner, green 1, yellow 0.5, red 0; magenta: no partner.</figcaption></figure>
<h3>The buildings that agree least</h3>
<table><tr><th>A id</th><th>B id</th><th>paired by</th><th>footprint IoU</th><th>eaves</th><th>ridge</th>
<th>volume</th><th>roof A / B</th></tr>
{}</table>
<p>Every building is in the JSON file.</p>
{}
<h2>Cost</h2>
<table><tr><th></th><th>A</th><th>B</th></tr>
{}</table>
<script>{}</script>
</body></html>
)",
        kStyle, escapeXml(r.a.name), escapeXml(r.b.name), c.matchedById, c.matchedByOverlap, c.onlyA, c.onlyB,
        c.meanFootprintIou, c.meanAbsEavesError, c.meanAbsRidgeError, c.meanAbsVolumeError * 100, c.roofAgreement * 100,
        r.mapA.grid.cell,
        c.groundPlans ? "the buildings' ground plans"
                      : "the cells a building tops seen from above (overhangs included)",
        dataUri(districtErrorMap(r, 1000)), buildingRows(c, 50), sections, costRows(r.a, r.b), kScript);
}

}  // namespace veduta
