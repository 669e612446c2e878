// An SVG parses (expat) and holds one shape per bench: a vector file stays editable bench by
// bench, unlike the grouped fills used on raster surfaces.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <expat.h>
#include <gtest/gtest.h>

#include "dragon/render.hpp"

namespace dragon {
namespace {

struct SvgCount {
    int paths = 0;
    std::map<std::string, int> fills;  // "fill:rgb(...)" of each <path>
};

void start(void* data, const XML_Char* name, const XML_Char** attrs) {
    auto* c = static_cast<SvgCount*>(data);
    if (std::string(name) != "path") return;
    ++c->paths;
    for (int i = 0; attrs[i]; i += 2) {
        if (std::string(attrs[i]) != "style") continue;
        const std::string style = attrs[i + 1];
        const auto at = style.find("fill:rgb(");
        if (at != std::string::npos) ++c->fills[style.substr(at, style.find(')', at) - at + 1)];
    }
}
void end(void*, const XML_Char*) {}

std::string cairo_rgb(Rgba c) {
    // Cairo writes colours as percentages with six decimals, e.g. rgb(80%,16.078431%,16.078431%).
    auto pct = [](double v) {
        std::string s = std::to_string(v * 100.0);
        while (!s.empty() && s.back() == '0') s.pop_back();
        if (!s.empty() && s.back() == '.') s.pop_back();
        return s + "%";
    };
    return "fill:rgb(" + pct(c.r) + "," + pct(c.g) + "," + pct(c.b) + ")";
}

TEST(Svg, ParsesAndHoldsOneShapePerBench) {
    Scenario sc;
    const Simulation sim(sc);
    SceneOptions o;
    o.theme = load_theme("light", std::string(DRAGON_SOURCE_DIR) + "/assets");
    const Scene scene = make_scene(sim, sim.frame(300.0), o);
    const auto dir = std::filesystem::path(DRAGON_TEST_TMP) / "svg";
    std::filesystem::create_directories(dir);
    const auto file = dir / "t300.svg";
    render_svg(scene, 800, 800, file.string());

    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    SvgCount count;
    XML_Parser p = XML_ParserCreate(nullptr);
    XML_SetUserData(p, &count);
    XML_SetElementHandler(p, start, end);
    const bool parsed = XML_Parse(p, text.data(), static_cast<int>(text.size()), 1) == XML_STATUS_OK;
    const std::string err = parsed ? "" : XML_ErrorString(XML_GetErrorCode(p));
    XML_ParserFree(p);
    ASSERT_TRUE(parsed) << err;

    const int n = sc.bench.bench_count;
    EXPECT_EQ(count.fills[cairo_rgb(o.theme.head)], 1);
    EXPECT_EQ(count.fills[cairo_rgb(o.theme.tail)], 1);
    EXPECT_EQ(count.fills[cairo_rgb(o.theme.body)], n - 2);
    EXPECT_GE(count.paths, n);
}

}  // namespace
}  // namespace dragon
