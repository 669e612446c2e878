// libav's negative return codes as the library's exceptions with context (the video layer's one
// error style): a failure of the encoder or the muxer is a SolverError, a failed write of the
// file a FileError naming it.
#pragma once

#include <string>

#include "dragon/errors.hpp"

extern "C" {
#include <libavutil/error.h>
}

namespace dragon::av {

inline std::string error_text(int code) {
    char buf[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, buf, sizeof buf);
    return buf;
}

// Throws SolverError("what: libav's message") when code < 0; returns code otherwise.
inline int check(int code, const std::string& what) {
    if (code < 0) throw SolverError(what + ": " + error_text(code));
    return code;
}

// Throws FileError (cannot `action` `path`: libav's message) when code < 0.
inline int check_file(int code, const std::string& path, const std::string& action) {
    if (code < 0) throw FileError(path, action, error_text(code));
    return code;
}

}  // namespace dragon::av
