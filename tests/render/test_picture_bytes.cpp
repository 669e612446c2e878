// Pictures in memory (render_bytes, render_rgba) are the files' pictures: the same bytes as
// render_png and render_svg write, the same page as render_pdf, the same pixels as the PNG
// decoded by Cairo's own reader.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <cairo.h>
#include <gtest/gtest.h>

#include "dragon/picture_bytes.hpp"
#include "dragon/render.hpp"

namespace dragon {
namespace {

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct PictureBytes : ::testing::Test {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / ("picture_bytes_" + std::to_string(::getpid()));
    Scene scene;
    void SetUp() override {
        std::filesystem::create_directories(dir);
        const Simulation sim{Scenario{}};
        SceneOptions o;
        o.theme = load_theme("light", std::string(DRAGON_SOURCE_DIR) + "/assets");
        o.colour_by_speed = true;
        scene = make_scene(sim, sim.frame(300.0), o);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
};

TEST_F(PictureBytes, PngAndSvgAreTheFilesBytes) {
    render_png(scene, 320, 240, (dir / "a.png").string());
    render_svg(scene, 320, 240, (dir / "a.svg").string());
    EXPECT_EQ(render_bytes(scene, 320, 240, PictureType::png), slurp(dir / "a.png"));
    // Cairo numbers its surfaces process-wide: the SVG's ids say how many came before.
    const std::regex surface_id("surface[0-9]+");
    EXPECT_EQ(std::regex_replace(render_bytes(scene, 320, 240, PictureType::svg), surface_id, "surface"),
              std::regex_replace(slurp(dir / "a.svg"), surface_id, "surface"));
}

TEST_F(PictureBytes, PdfHasTheFilesPage) {
    render_pdf(scene, 320, 240, (dir / "a.pdf").string());
    const std::string mem = render_bytes(scene, 320, 240, PictureType::pdf), file = slurp(dir / "a.pdf");
    EXPECT_EQ(mem.substr(0, 5), "%PDF-");
    // 320 x 240 px at 96 px to the inch: 240 x 180 pt.
    EXPECT_NE(mem.find("/MediaBox [ 0 0 240 180 ]"), std::string::npos);
    EXPECT_NE(file.find("/MediaBox [ 0 0 240 180 ]"), std::string::npos);
}

TEST_F(PictureBytes, RgbaIsThePngsPixels) {
    const int w = 200, h = 150;
    render_png(scene, w, h, (dir / "b.png").string());
    cairo_surface_t* png = cairo_image_surface_create_from_png((dir / "b.png").c_str());
    ASSERT_EQ(cairo_surface_status(png), CAIRO_STATUS_SUCCESS);
    const std::vector<std::uint8_t> rgba = render_rgba(scene, w, h);
    ASSERT_EQ(rgba.size(), static_cast<std::size_t>(w * h * 4));
    const unsigned char* data = cairo_image_surface_get_data(png);
    const int stride = cairo_image_surface_get_stride(png);
    int differ = 0, coloured = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto p = reinterpret_cast<const std::uint32_t*>(data + y * stride)[x];
            const std::uint8_t* q = &rgba[static_cast<std::size_t>((y * w + x) * 4)];
            const bool same = q[0] == ((p >> 16) & 255) && q[1] == ((p >> 8) & 255) && q[2] == (p & 255) && q[3] == 255;
            differ += !same;
            coloured += q[0] != q[1] || q[1] != q[2];
        }
    cairo_surface_destroy(png);
    EXPECT_EQ(differ, 0);
    EXPECT_GT(coloured, 100);  // the speed colours are there: not a blank or grey page
}

TEST_F(PictureBytes, RefusesWhatTheFilesRefuse) {
    EXPECT_THROW(render_bytes(scene, 8, 240, PictureType::png), InputError);
    EXPECT_THROW(render_rgba(scene, 320, 20000), InputError);
    EXPECT_THROW(picture_type("jpeg"), InputError);
    EXPECT_EQ(picture_type("svg"), PictureType::svg);
}

}  // namespace
}  // namespace dragon
