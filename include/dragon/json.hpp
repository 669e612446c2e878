// JSON as the library's answers are written: objects with their keys in the order written
// (nlohmann's ordered_json), and text in which every number is the shortest decimal of the value
// meant. One formatter for the CLI's --json, sweep rows, summary.json and Python's to_dict().
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace dragon {

// A JSON value whose objects keep their keys in the order written.
using Json = nlohmann::ordered_json;

// The value a computed double stands for: rounded to 15 significant digits (0.0025, not
// 0.002500000000000001; 0.979435, not 0.9794349999999999), never -0.
double meant(double v);
// `v` as JSON text with every number the shortest decimal of the value meant, whole numbers
// without ".0" ("times":[0,300]), NaN and infinities as null; on one line, or indented by
// `indent` spaces a level.
std::string json_text(const Json& v, int indent = -1);
// json_text(v) on one line, telling `leaf` the text of each leaf inside it under its key path
// ("first_contact.time"; an array, a scalar or an empty object is a leaf; a scalar root's path is
// ""), in the order written: the characters the whole text holds for it, each printed once.
std::string json_text_with_leaves(const Json& v,
                                  const std::function<void(const std::string& path, std::string_view text)>& leaf);

}  // namespace dragon
