#include "dragon/errors.hpp"

#include <utility>

#include <fmt/format.h>

namespace dragon {

InputError::InputError(const std::string& message) : std::runtime_error(message) {}

InputError::InputError(Key key, std::string value, std::string allowed)
    : std::runtime_error(fmt::format("{} {} is not allowed: {}", key_info(key).words, value, allowed)),
      key_(key),
      value_(std::move(value)),
      allowed_(std::move(allowed)) {}

InputError::InputError(Key key, std::string value, std::string allowed, const std::string& message)
    : std::runtime_error(message), key_(key), value_(std::move(value)), allowed_(std::move(allowed)) {}

FileError::FileError(std::string path, std::string action, std::string reason)
    : std::runtime_error(fmt::format("cannot {} '{}': {}", action, path, reason)),
      path_(std::move(path)),
      reason_(std::move(reason)) {}

std::string error_value(double v) { return fmt::format("{}", v); }

}  // namespace dragon
