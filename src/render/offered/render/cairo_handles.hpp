// RAII for the Cairo handles: unique_ptr aliases whose deleters call the matching destroy
// function, so no code path can leak a context or a surface.
#pragma once

#include <memory>

#include <cairo.h>

namespace dragon::cairo {

struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const noexcept { cairo_surface_destroy(s); }
};
struct ContextDeleter {
    void operator()(cairo_t* c) const noexcept { cairo_destroy(c); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using Context = std::unique_ptr<cairo_t, ContextDeleter>;

// Starts a picture in the layout log (render/paint.hpp) when one records: an image surface's
// pixels (a vector surface's page is logged by whoever knows it).
void log_new_surface(cairo_surface_t* target);

// A context on a surface (cairo_create references the surface, so either may go first).
inline Context make_context(cairo_surface_t* target) {
    log_new_surface(target);
    return Context(cairo_create(target));
}

}  // namespace dragon::cairo
