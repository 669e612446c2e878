// libFuzzer target: theme files (--theme FILE.toml, a storyboard's [film] theme).
//
// Input: the bytes of a theme file.
//
// Properties:
//  - load_theme returns or throws InputError: nothing else escapes (toml++'s parse errors, a
//    deep table's recursion, fontconfig on any font name);
//  - a theme it returns is drawable: every colour's components in [0, 1], a speed ramp of 2 to
//    256 colours, a name and a font of 1 to 200 characters.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include "dragon/render.hpp"
#include "fuzz_check.hpp"

namespace {

using namespace dragon;

const std::string& theme_path() {
    static const std::string path = "/tmp/dragon-fuzz-theme-" + std::to_string(::getpid()) + ".toml";
    return path;
}

void write_file(const std::string& path, const std::string& text) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    FUZZ_CHECK(f != nullptr, "cannot write %s", path.c_str());
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
}

void check_colour(const Rgba& c) {
    for (const double v : {c.r, c.g, c.b, c.a}) FUZZ_CHECK(v >= 0.0 && v <= 1.0, "a colour component %g", v);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    write_file(theme_path(), std::string(reinterpret_cast<const char*>(data), size));
    fuzz_context() = "a theme file of " + std::to_string(size) + " bytes";
    try {
        Theme t;
        try {
            t = load_theme(theme_path());
        } catch (const InputError&) {
            return 0;
        }
        for (const Rgba& c : {t.background, t.text, t.grid, t.guide, t.guide_out, t.s_curve, t.turning_space,
                              t.turning_fill, t.head, t.body, t.tail, t.outline, t.handle, t.highlight, t.collision,
                              t.contact})
            check_colour(c);
        FUZZ_CHECK(t.speed_ramp.size() >= 2 && t.speed_ramp.size() <= 256, "a ramp of %zu", t.speed_ramp.size());
        for (const Rgba& c : t.speed_ramp) check_colour(c);
        FUZZ_CHECK(!t.name.empty() && t.name.size() <= 200, "a name of %zu characters", t.name.size());
        FUZZ_CHECK(!t.font.empty() && t.font.size() <= 200, "a font of %zu characters", t.font.size());
    } catch (const std::exception& e) {
        FUZZ_CHECK(false, "unexpected exception: %s", e.what());
    }
    return 0;
}
