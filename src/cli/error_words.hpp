// The library's errors worded for the command line: a value the library names by its key
// (Key::to, dragon/keys.hpp) is named by the flag that set it ("--to"), and each kind of error
// maps to its exit code.
#pragma once

#include <string>

#include "dragon/errors.hpp"

namespace dragon::cli {

// The one line an InputError becomes: "--to 5000 is not allowed: ..." when its key is a flag's
// value, else the library's own sentence.
std::string word(const InputError& e);

// Whether some command of the tool sets `key` with a flag of its name (--pitch, --from); the
// others (a table's frame count, a study's entry radius) are the library's and Python's only.
bool takes_flag(Key key);
// The flag of a key that takes one, as the commands spell it: "--pitch", "--from/--to", a
// switch on by default "--no-guides", one whose default depends on the command "--[no-]legend".
std::string flag_spelling(Key key);

}  // namespace dragon::cli
