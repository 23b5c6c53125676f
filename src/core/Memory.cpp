#include "gridcar/core/Memory.h"

#include <cstdio>
#include <unistd.h>

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

}  // namespace gridcar
