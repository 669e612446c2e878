#include "yuv_convert.hpp"

namespace dragon::video {

namespace {
// BT.709 with the limited-range scale folded in (219/255 for luma, 224/255 for chroma),
// times 2^16. Each chroma row sums to zero so grey stays exactly grey.
constexpr std::int32_t yr = 11966, yg = 40254, yb = 4064;
constexpr std::int32_t ur = -6596, ug = -22188, ub = 28784;
constexpr std::int32_t vr = 28784, vg = -26145, vb = -2639;
constexpr std::int32_t half = 1 << 15;

inline std::int32_t red(std::uint32_t p) { return static_cast<std::int32_t>((p >> 16) & 0xffu); }
inline std::int32_t green(std::uint32_t p) { return static_cast<std::int32_t>((p >> 8) & 0xffu); }
inline std::int32_t blue(std::uint32_t p) { return static_cast<std::int32_t>(p & 0xffu); }

inline std::uint8_t luma(std::uint32_t p) {
    return static_cast<std::uint8_t>(16 + ((yr * red(p) + yg * green(p) + yb * blue(p) + half) >> 16));
}
}  // namespace

// On x86-64 built twice, for AVX2 (twice the lanes, ~1.7x faster here) and for any CPU; the
// loader picks the one this CPU runs. Not under ThreadSanitizer: the loader runs the picker (an
// ifunc resolver) before TSan's runtime is up, and the program crashes on start.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_THREAD__)
#define DRAGON_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define DRAGON_VECTOR_CLONES
#endif

DRAGON_VECTOR_CLONES
void argb32_to_yuv420p(const std::uint8_t* argb32, int stride, int width, int height, Yuv420Planes out) {
    for (int y = 0; y < height; y += 2) {
        const auto* row0 = reinterpret_cast<const std::uint32_t*>(argb32 + static_cast<std::ptrdiff_t>(y) * stride);
        const auto* row1 = reinterpret_cast<const std::uint32_t*>(argb32 + static_cast<std::ptrdiff_t>(y + 1) * stride);
        std::uint8_t* y0 = out.y + static_cast<std::ptrdiff_t>(y) * out.y_stride;
        std::uint8_t* y1 = y0 + out.y_stride;
        for (int x = 0; x < width; ++x) {
            y0[x] = luma(row0[x]);
            y1[x] = luma(row1[x]);
        }
        std::uint8_t* u = out.u + static_cast<std::ptrdiff_t>(y / 2) * out.u_stride;
        std::uint8_t* v = out.v + static_cast<std::ptrdiff_t>(y / 2) * out.v_stride;
        for (int x = 0; x < width / 2; ++x) {
            const std::uint32_t a = row0[2 * x], b = row0[2 * x + 1], c = row1[2 * x], d = row1[2 * x + 1];
            const std::int32_t r = red(a) + red(b) + red(c) + red(d);
            const std::int32_t g = green(a) + green(b) + green(c) + green(d);
            const std::int32_t bl = blue(a) + blue(b) + blue(c) + blue(d);
            // Sums of four: two more fractional bits.
            u[x] = static_cast<std::uint8_t>(128 + ((ur * r + ug * g + ub * bl + (half << 2)) >> 18));
            v[x] = static_cast<std::uint8_t>(128 + ((vr * r + vg * g + vb * bl + (half << 2)) >> 18));
        }
    }
}

}  // namespace dragon::video
