#include "wording.hpp"

#include <vector>

#include <fmt/format.h>

namespace dragon::cli {

std::string count_of(long long n, const std::string& one, const std::string& many) {
    return fmt::format("{} {}", n, n == 1 ? one : many.empty() ? one + "s" : many);
}

}  // namespace dragon::cli
