#include "gridcar/spaces/Lattice.h"

namespace gridcar
{
constexpr int Moves::dcol[8];
constexpr int Moves::drow[8];

int headingBin(double yaw, int bins)
{
    if (!std::isfinite(yaw) || bins <= 0) return 0;
    long k = std::lround(std::floor(yaw / (2.0 * M_PI / bins) + 0.5));
    k %= bins;
    if (k < 0) k += bins;
    return int(k);
}

}  // namespace gridcar
