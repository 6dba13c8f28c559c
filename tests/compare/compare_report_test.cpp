// The report of `veduta compare`: one HTML page that carries its pictures and a JSON file of
// the figures, here of a box against the same box moved by a metre.
#include <gtest/gtest.h>

#include <regex>

#include "compare/compare_report.h"
#include "scene/shapes.h"

namespace veduta {
namespace {

RenderScene box(float x) {
    RenderSceneBuilder builder;
    builder.addMesh(makeShape(ShapeSpec{}), Transform::translate({x, 0, 0}) * Transform::scale({10, 10, 10}), 1, 5);
    builder.recordBuilding({5, 0, 10, 10, "flat", {}});
    return std::move(builder).build();
}

size_t count(const std::string &text, const std::string &what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(CompareReport, PageAndFigures) {
    RenderScene a = box(0), b = box(1);
    CompareReport report;
    report.a.name = "a<&>.gml", report.b.name = "b.xml";
    GroundGrid grid = gridOverBuildings(a, b, 100'000);
    report.mapA = topDownHeights(a, grid), report.mapB = topDownHeights(b, grid);
    report.buildings = compareBuildings(a, report.mapA, b, report.mapB);
    ViewResult view;
    view.view = {"overview", Camera{}};
    view.renderA = view.renderB = view.previewA = view.previewB = RgbaImage(8, 4);
    view.rendered = compareRenderings(view.renderA, view.renderB);
    report.views.push_back(view);

    std::string page = reportHtml(report);
    EXPECT_NE(page.find("a&lt;&amp;&gt;.gml"), std::string::npos);  // names are escaped
    // The district map, and per view A, B, their difference, the slider's two and the two previews.
    EXPECT_EQ(count(page, "<img "), 1u + 7u);
    EXPECT_EQ(count(page, "src=\"data:image/png;base64,"), 8u);
    EXPECT_EQ(page.find("src=\"http"), std::string::npos);  // nothing from elsewhere
    EXPECT_NE(page.find("images loaded"), std::string::npos);

    std::string json = reportJson(report);
    EXPECT_TRUE(std::regex_search(json, std::regex("\"matched_by_id\": 1")));
    EXPECT_TRUE(std::regex_search(json, std::regex("\"mean_footprint_iou\": 0\\.81818")));
    EXPECT_TRUE(std::regex_search(json, std::regex("\"psnr\": null")));  // equal images: +infinity
    EXPECT_EQ(count(json, "{"), count(json, "}"));
}

}  // namespace
}  // namespace veduta
