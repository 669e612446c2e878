#include "dragon/language.hpp"

#include "dragon/errors.hpp"

namespace dragon {

Language parse_language(std::string_view code) {
    if (code == "en") return Language::en;
    if (code == "zh") return Language::zh;
    throw InputError(Key::lang, std::string(code), "use en (English) or zh (Chinese)");
}

std::string language_code(Language language) { return language == Language::zh ? "zh" : "en"; }

}  // namespace dragon
