// A property check for the fuzz targets: on failure, say what and where (and what input it was
// about, from fuzz_context()), then abort so that libFuzzer saves the input as a crash.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

// What the current input describes, in words (set by the target; printed on a failure).
inline std::string& fuzz_context() {
    static std::string context;
    return context;
}

#define FUZZ_CHECK(cond, ...)                                                   \
    do {                                                                        \
        if (!(cond)) {                                                          \
            std::fprintf(stderr, "%s:%d: property failed: %s\n  ", __FILE__,    \
                         __LINE__, #cond);                                      \
            std::fprintf(stderr, __VA_ARGS__);                                  \
            std::fprintf(stderr, "\n  input: %s\n", fuzz_context().c_str());    \
            std::abort();                                                       \
        }                                                                       \
    } while (0)
