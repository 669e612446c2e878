#include "dragon/window.hpp"

#include <fmt/format.h>

namespace dragon {

std::string to_string(const Along& a) { return fmt::format("{} {}", a.value, a.unit == Along::Unit::metres ? "m" : "s"); }

}  // namespace dragon
