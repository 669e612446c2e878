// The library's errors, as data. Each says what went wrong in the library's own terms; an
// application words it for its users (the dragon CLI names its flags) and maps its kind to an
// exit code. Three kinds:
//  - InputError: a value the caller gave cannot be used (out of range, malformed). It carries
//    which value (`key`: Key::to, Key::grid, described in dragon/keys.hpp), the value as given,
//    and what is allowed, or only a sentence when no single value is at fault. A front end finds
//    the value by its key, never by the sentence's words.
//  - SolverError: the computation could not reach an answer; not the caller's input.
//  - FileError: a file could not be read or written: which, and why.
#pragma once

#include <stdexcept>
#include <string>

#include "dragon/keys.hpp"

namespace dragon {

// A value the caller gave cannot be used: which (field), as given (value), and what is allowed.
class InputError : public std::runtime_error {
public:
    // A sentence only (a malformed file, a rule between several values).
    explicit InputError(const std::string& message);
    // One value: what() is "{words} {value} is not allowed: {allowed}", the key's words.
    InputError(Key key, std::string value, std::string allowed);
    // One value, said in a sentence of its own.
    InputError(Key key, std::string value, std::string allowed, const std::string& message);

    Key key() const { return key_; }                          // Key::none for a sentence-only error
    std::string_view field() const { return key_info(key_).words; }  // the key in words ("" for none)
    const std::string& value() const { return value_; }      // the value as given
    const std::string& allowed() const { return allowed_; }  // what would be allowed, in words

private:
    Key key_ = Key::none;
    std::string value_, allowed_;
};

// The computation could not reach an answer: not the caller's input.
class SolverError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A file could not be read or written: which, and why.
class FileError : public std::runtime_error {
public:
    // what() is "cannot {action} '{path}': {reason}".
    FileError(std::string path, std::string action, std::string reason);
    const std::string& path() const { return path_; }      // the file, as named
    const std::string& reason() const { return reason_; }  // why it failed (the system's words)

private:
    std::string path_, reason_;
};

// A number as an error shows it: as short as it reads back exactly (5000, 0.1, 1e+300), never
// three hundred digits.
std::string error_value(double v);

}  // namespace dragon
