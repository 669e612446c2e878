// The print-size flags of the drawing commands (render, figures, sweep --plot, film posters):
// a picture's width on the page and its text's size in points, instead of pixels.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "dragon/picture_size.hpp"

namespace dragon::cli {

class PrintFlags {
public:
    // Registers --print, --width-in, --width-cm, --font-pt and --dpi on `sub`.
    void add_to(CLI::App* sub);
    // The print size the flags ask for (--print's preset, or a 3.5 in column at 8 pt and 300
    // dpi, with the other flags over it); nullopt when none is given (sizes in pixels).
    // Throws InputError naming the flag whose value is outside its range.
    std::optional<PrintSize> resolve() const;
    bool given() const;

private:
    std::optional<std::string> preset_;
    std::optional<double> width_in_, width_cm_, font_pt_, dpi_;
};

}  // namespace dragon::cli
