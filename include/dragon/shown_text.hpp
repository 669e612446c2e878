// How a message shows text the user gave: part of the core (a scenario's or a sweep's text is
// parsed there, and its errors quote it), with no file behind it.
#pragma once

#include <cstddef>
#include <string>

namespace dragon {

// How a message shows text the user gave (a path, a key, a value): control characters escaped
// (a newline as \n, a NUL as \x00), so that a message stays one line, and text longer than
// `most` characters cut, saying how long it was.
std::string shown_text(const std::string& text, std::size_t most = 80);

}  // namespace dragon
