// --from and --to as every command with a window of the motion takes them: a time in seconds
// (12.5, or 12.5s) or a length of head travel in metres (-100m). The chain's shape depends on
// the head's travel alone, so the default windows are travel (the contest's "100 s either side
// of the turn" is 100 m at its 1 m/s) and answer the same at any head speed.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "dragon/window.hpp"

namespace dragon::cli {

// "12.5", "12.5s" or "12.5 s": seconds; "-100m" or "-100 m": metres of head travel. Throws
// InputError naming `flag` otherwise.
Along parse_along(const std::string& flag, const std::string& text);

class WindowFlags {
public:
    // Registers --from and --to on `sub`, with what each means there and its default.
    void add_to(CLI::App* sub, const std::string& what_from, const std::string& what_to);
    // The window: the flags given over `defaults` (an open end stays +inf).
    RunWindow resolve(const RunWindow& defaults) const;
    bool given() const { return from_.has_value() || to_.has_value(); }
    CLI::Option* from_option() const { return from_opt_; }
    CLI::Option* to_option() const { return to_opt_; }

private:
    std::optional<std::string> from_, to_;
    CLI::Option* from_opt_ = nullptr;
    CLI::Option* to_opt_ = nullptr;
};

}  // namespace dragon::cli
