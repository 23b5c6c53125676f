#pragma once
/// @file Envelope.h
/// @brief The distance transform's parts shared by DistanceField's full computation and its
/// update: Felzenszwalb and Huttenlocher's 1D lower envelope, and ranges shared among threads.

#include <algorithm>
#include <cstdint>
#include <thread>
#include <vector>

namespace gridcar::detail
{
inline constexpr std::int64_t kInf = std::int64_t(1) << 50;

/// Felzenszwalb-Huttenlocher lower envelope in 1D over positions 0..n-1 with costs f
/// (kInf = no site). Writes d[q] = min_p (q-p)^2 + f[p] and arg[q] = that p (-1 if no site).
struct Envelope
{
    std::vector<int> v;
    std::vector<double> z;
    void resize(int n)
    {
        v.resize(std::size_t(n));
        z.resize(std::size_t(n) + 1);
    }
    void run(const std::int64_t *f, int n, std::int64_t *d, int *arg)
    {
        int k = -1;
        for (int q = 0; q < n; ++q)
        {
            if (f[q] >= kInf) continue;
            if (k < 0)
            {
                k = 0;
                v[0] = q;
                z[0] = -1e300;
                z[1] = 1e300;
                continue;
            }
            double s;
            while (true)
            {
                const int p = v[std::size_t(k)];
                s = (double(f[q] + std::int64_t(q) * q) - double(f[p] + std::int64_t(p) * p)) / (2.0 * (q - p));
                if (s <= z[std::size_t(k)] && k > 0) --k;
                else break;
            }
            if (s <= z[std::size_t(k)])  // k == 0 and the new parabola dominates everywhere
            {
                v[0] = q;
                z[0] = -1e300;
                z[1] = 1e300;
                continue;
            }
            ++k;
            v[std::size_t(k)] = q;
            z[std::size_t(k)] = s;
            z[std::size_t(k) + 1] = 1e300;
        }
        if (k < 0)
        {
            for (int q = 0; q < n; ++q)
            {
                d[q] = kInf;
                arg[q] = -1;
            }
            return;
        }
        int j = 0;
        for (int q = 0; q < n; ++q)
        {
            while (z[std::size_t(j) + 1] < q) ++j;
            const int p = v[std::size_t(j)];
            d[q] = std::int64_t(q - p) * (q - p) + f[p];
            arg[q] = p;
        }
    }
};

/// Runs @p part(begin, end) over [0, n) split among the machine's threads (up to 4) where n
/// items of @p work each make it worth it, else at once on this thread.
template <class Part>
void parallelRanges(int n, std::size_t work, const Part &part)
{
    const unsigned hw = std::max(1u, std::min(4u, std::thread::hardware_concurrency()));
    const int parts = work < (std::size_t(1) << 20) ? 1 : int(std::min<unsigned>(hw, unsigned(std::max(1, n))));
    if (parts <= 1)
    {
        part(0, n);
        return;
    }
    std::vector<std::thread> threads;
    for (int k = 1; k < parts; ++k) threads.emplace_back(part, n * k / parts, n * (k + 1) / parts);
    part(0, n / parts);
    for (std::thread &t : threads) t.join();
}

}  // namespace gridcar::detail
