// A parameterised test's name from the text of its case, for INSTANTIATE_TEST_SUITE_P's name
// generator: "simulate --pitch -0.5 -o @OUT" is "3_simulate_pitch_minus0p5_o_OUT" as case 3.
// gtest allows only letters, digits and '_': letters and digits are kept, a minus sign before a
// digit is "minus", a point between digits "p", and any other run of characters one '_'. The
// case's index in front keeps two cases that read alike apart; the rest is cut at 60 characters.
#pragma once

#include <cctype>
#include <cstddef>
#include <string>

namespace dragon_test {

inline std::string param_name(std::size_t index, const std::string& text) {
    const auto digit = [&](std::size_t k) { return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k])); };
    std::string name = std::to_string(index) + "_";
    for (std::size_t k = 0; k < text.size() && name.size() < 60; ++k) {
        const char c = text[k];
        if (std::isalnum(static_cast<unsigned char>(c))) name += c;
        else if (c == '-' && digit(k + 1) && (k == 0 || !std::isalnum(static_cast<unsigned char>(text[k - 1]))))
            name += "minus";
        else if (c == '.' && k > 0 && digit(k - 1) && digit(k + 1)) name += 'p';
        else if (name.back() != '_') name += '_';
    }
    while (name.size() > 1 && name.back() == '_') name.pop_back();
    return name;
}

}  // namespace dragon_test
