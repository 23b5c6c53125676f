#include "gridcar/core/Memory.h"

#include <cstdint>
#include <cstdio>
#include <unistd.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace gridcar
{
double residentMegabytes()
{
    std::FILE *f = std::fopen("/proc/self/statm", "r");
    if (!f) return -1.0;
    unsigned long size = 0, resident = 0;
    const int n = std::fscanf(f, "%lu %lu", &size, &resident);
    std::fclose(f);
    if (n != 2) return -1.0;
    return double(resident) * double(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

void adviseHugePages(void *p, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
    if (!p || bytes < 2 * kHuge) return;
    const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t begin = (a + kHuge - 1) & ~(kHuge - 1), end = (a + bytes) & ~(kHuge - 1);
    if (end > begin) (void)::madvise(reinterpret_cast<void *>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

}  // namespace gridcar
