#include "storyboard_values.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <fmt/format.h>

#include "dragon/input_file.hpp"
#include "dragon/picture_size.hpp"

namespace dragon::film {

void Where::fail(const std::string& key, const std::string& why) const { throw StoryboardError(file, shot, name, key, why); }

void check_keys(const Where& w, const toml::table& t, const std::set<std::string>& allowed, const std::string& what,
                const std::string& prefix) {
    for (const auto& [k, node] : t) {
        (void)node;
        const std::string key(k.str());
        if (allowed.count(key)) continue;
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        w.fail(prefix + shown_text(key), fmt::format("is not a key of {} (allowed: {})", what, list));
    }
}

double number(const Where& w, const toml::node& n, const std::string& key) {
    std::optional<double> v = n.value<double>();
    if (!v && n.is_integer()) v = static_cast<double>(*n.value_exact<std::int64_t>());  // huge: a range says so
    if (!v || !std::isfinite(*v)) w.fail(key, "must be a finite number");
    return *v;
}

double positive(const Where& w, const toml::node& n, const std::string& key, double most) {
    const double v = number(w, n, key);
    if (!(v > 0 && v <= most)) w.fail(key, fmt::format("= {} is not allowed: use more than 0, up to {:g}", v, most));
    return v;
}

bool boolean(const Where& w, const toml::node& n, const std::string& key) {
    const std::optional<bool> v = n.value<bool>();
    if (!v) w.fail(key, "must be true or false");
    return *v;
}

std::string text(const Where& w, const toml::node& n, const std::string& key) {
    const std::optional<std::string> v = n.value<std::string>();
    if (!v) w.fail(key, "must be a string");
    // Drawing text costs time by its length on every frame it shows on (a 5 MB title took 19 s a
    // frame): no text on a frame is longer than a few lines.
    if (v->size() > kMaxStoryboardText)
        w.fail(key, fmt::format("\"{}\" is not allowed: a text has at most {} characters", shown_text(*v, 40),
                                kMaxStoryboardText));
    return *v;
}

TimeRef time_ref(const Where& w, const toml::node& n, const std::string& key) {
    if (n.is_number()) return {TimeRef::Anchor::time, number(w, n, key)};
    if (!n.is_string())
        w.fail(key, "must be a moment: a number of seconds, or a string: head travel in metres (\"-100 m\"), or "
                    "collision, boundary or end, optionally with + or - seconds (\"collision - 5\")");
    const std::string s = text(w, n, key);
    const auto bad = [&] {
        w.fail(key, fmt::format("'{}' is not a moment: give seconds, head travel in metres (\"-100 m\"), or "
                                "collision, boundary or end, optionally with + or - seconds (\"collision - 5\")", shown_text(s, 40)));
    };
    if (!n.is_string()) bad();
    {
        // Head travel: a number and "m".
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (end != s.c_str() && std::isfinite(v)) {
            std::string rest = end;
            rest.erase(0, rest.find_first_not_of(' '));
            if (rest == "m") return {TimeRef::Anchor::travel, v};
        }
    }
    std::size_t i = 0;
    while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
    const std::string word = s.substr(0, i);
    TimeRef r;
    if (word == "collision") r.anchor = TimeRef::Anchor::collision;
    else if (word == "boundary") r.anchor = TimeRef::Anchor::boundary;
    else if (word == "end") r.anchor = TimeRef::Anchor::end;
    else bad();
    while (i < s.size() && s[i] == ' ') ++i;
    if (i == s.size()) return r;
    const char sign = s[i++];
    if (sign != '+' && sign != '-') bad();
    const std::string rest = s.substr(i);
    char* end = nullptr;
    const double v = std::strtod(rest.c_str(), &end);
    if (rest.find_first_not_of(' ') == std::string::npos || end == rest.c_str() || !std::isfinite(v) || v < 0) bad();
    for (const char* c = end; *c; ++c)
        if (*c != ' ') bad();
    r.offset = sign == '+' ? v : -v;
    return r;
}

namespace {
double extent(const Where& w, const toml::node& n, const std::string& key) {
    const double v = number(w, n, key);
    if (!(v >= kMinViewExtent && v <= kMaxViewExtent))
        w.fail(key, fmt::format("= {} is not allowed: a window is {:g}..{:g} m across", v, kMinViewExtent, kMaxViewExtent));
    return v;
}
}  // namespace

Window window(const Where& w, const toml::node& n, const std::string& key) {
    if (n.is_string()) {
        const std::string s = *n.value<std::string>();
        if (s == "fit") return {};
        if (s == "head") return {Window::Kind::head, Vec2::Zero(), 12.0};
        w.fail(key, fmt::format("'{}' is not a window: use \"fit\", \"head\", {{follow = M}}, {{centre = [X, Y], "
                                "extent = M}} or {{contact = M}}", shown_text(s)));
    }
    const toml::table* t = n.as_table();
    if (!t) w.fail(key, "must be \"fit\", \"head\" or a table ({follow = M}, {centre = [X, Y], extent = M}, {contact = M})");
    if (const toml::node* f = t->get("follow")) {
        check_keys(w, *t, {"follow"}, "a followed window", key + ".");
        return {Window::Kind::head, Vec2::Zero(), extent(w, *f, key + ".follow")};
    }
    if (const toml::node* c = t->get("contact")) {
        check_keys(w, *t, {"contact"}, "a window about the contact", key + ".");
        return {Window::Kind::contact, Vec2::Zero(), extent(w, *c, key + ".contact")};
    }
    check_keys(w, *t, {"centre", "extent"}, "a fixed window", key + ".");
    const toml::array* c = t->get_as<toml::array>("centre");
    const toml::node* e = t->get("extent");
    if (!c || c->size() != 2 || !e) w.fail(key, "a fixed window needs centre = [X, Y] and extent = M (metres)");
    Window out{Window::Kind::fixed, {number(w, *c->get(0), key + ".centre"), number(w, *c->get(1), key + ".centre")},
               extent(w, *e, key + ".extent")};
    if (std::max(std::abs(out.centre.x()), std::abs(out.centre.y())) > kMaxViewCentre)
        w.fail(key + ".centre", fmt::format("is not allowed: each coordinate within {:g} m", kMaxViewCentre));
    return out;
}

CameraMove camera(const Where& w, const toml::node& n, const std::string& key) {
    const toml::table* t = n.as_table();
    if (!t || !t->contains("from")) return {window(w, n, key), std::nullopt, Ease::in_out};
    check_keys(w, *t, {"from", "to", "ease"}, "a camera move", key + ".");
    CameraMove m{window(w, *t->get("from"), key + ".from"), std::nullopt, Ease::in_out};
    if (const toml::node* to = t->get("to")) m.to = window(w, *to, key + ".to");
    if (const toml::node* e = t->get("ease")) {
        const std::string s = text(w, *e, key + ".ease");
        if (s == "linear") m.ease = Ease::linear;
        else if (s != "in-out") w.fail(key + ".ease", fmt::format("'{}' is not an easing: use \"in-out\" or \"linear\"", shown_text(s)));
    }
    return m;
}

std::pair<int, int> size(const Where& w, const toml::node& n, const std::string& key) {
    const std::string s = text(w, n, key);
    try {
        const PictureSize size = parse_picture_size(s, kMaxVideoSide);  // a film is a video
        return {size.width, size.height};
    } catch (const InputError& e) {
        w.fail(key, fmt::format("'{}' is not allowed: {}", shown_text(s), e.allowed()));
    }
}

}  // namespace dragon::film
