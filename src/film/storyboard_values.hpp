// Reading the values of a storyboard's keys: numbers, moments, windows, cameras, with every
// error naming the shot and the key.
#pragma once

#include <set>
#include <string>

#include <toml++/toml.h>

#include "dragon/film.hpp"

namespace dragon::film {

// Where in the storyboard a value comes from: the file, the shot (0: [film]) and its name.
struct Where {
    std::string file;
    int shot = 0;
    std::string name;
    [[noreturn]] void fail(const std::string& key, const std::string& why) const;
};

// Every key of `t` must be in `allowed` (the error lists them); `what` names the table.
void check_keys(const Where& w, const toml::table& t, const std::set<std::string>& allowed, const std::string& what,
                const std::string& prefix = "");

double number(const Where& w, const toml::node& n, const std::string& key);
// A number > 0 and finite, at most `most`.
double positive(const Where& w, const toml::node& n, const std::string& key, double most);
bool boolean(const Where& w, const toml::node& n, const std::string& key);
// A string of at most kMaxStoryboardText characters.
std::string text(const Where& w, const toml::node& n, const std::string& key);

// 412.5, "collision", "boundary - 30", "end-1".
TimeRef time_ref(const Where& w, const toml::node& n, const std::string& key);
// "fit", "head", {follow = 8}, {centre = [x, y], extent = 10}, {contact = 1.5}.
Window window(const Where& w, const toml::node& n, const std::string& key);
// A window, or {from = W, to = W, ease = "in-out" | "linear"}.
CameraMove camera(const Where& w, const toml::node& n, const std::string& key);
// "1280x720".
std::pair<int, int> size(const Where& w, const toml::node& n, const std::string& key);

}  // namespace dragon::film
