// libav's negative return codes as exceptions with context (the video layer's one error style).
#pragma once

#include <stdexcept>
#include <string>

extern "C" {
#include <libavutil/error.h>
}

namespace dragon::av {

inline std::string error_text(int code) {
    char buf[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, buf, sizeof buf);
    return buf;
}

// Throws std::runtime_error("what: libav's message") when code < 0; returns code otherwise.
inline int check(int code, const std::string& what) {
    if (code < 0) throw std::runtime_error(what + ": " + error_text(code));
    return code;
}

}  // namespace dragon::av
