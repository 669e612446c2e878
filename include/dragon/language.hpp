// The language of the words a picture, map or film carries by itself (titles, legends, axis
// names, captions, the clock's words): English or Chinese, the contest's own. Text a caller
// gives (an annotation, a storyboard's captions) is drawn as given, in any script.
#pragma once

#include <string>
#include <string_view>

namespace dragon {

// The languages the tool's own words come in.
enum class Language {
    en,  // English
    zh,  // Chinese (simplified), with the contest's terms: 板凳龙, 龙头, 龙身, 龙尾, 把手, 螺距, 调头空间
};

// "en" or "zh". Throws InputError (field "language") for any other text.
Language parse_language(std::string_view code);
// "en" or "zh".
std::string language_code(Language language);

}  // namespace dragon
