#include "wld/doom/line_plane.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace pvs::doom {

namespace {

__extension__ typedef __int128 Int128; // GCC and Clang; __extension__ keeps -Wpedantic quiet

// 65536 * v as an integer (16.16 fixed point), clamped to what the products below can hold.
int64_t fixed(double v)
{
    constexpr double kLimit = 1099511627776.0; // 2^40: coordinates up to 2^24 map units
    const double scaled = std::clamp(v * 65536.0, -kLimit, kLimit);
    return std::isfinite(scaled) ? std::llround(scaled) : 0;
}

} // namespace

LinePlane vertical_line_plane(double x, double y, double dx, double dy)
{
    int64_t ux = fixed(dx), uy = fixed(dy);
    if (ux == 0 && uy == 0)
        return {};
    const int64_t g = std::gcd(ux < 0 ? -ux : ux, uy < 0 ? -uy : uy);
    ux /= g;
    uy /= g;
    const Int128 numerator = Int128(uy) * fixed(x) - Int128(ux) * fixed(y);
    const double length = std::hypot(double(ux), double(uy));
    LinePlane plane;
    plane.nx = float(double(uy) / length);
    plane.ny = float(double(-ux) / length);
    plane.dist = float(double(numerator) / (length * 65536.0));
    return plane;
}

} // namespace pvs::doom
