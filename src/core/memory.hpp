#pragma once
// How much memory this process may hold, to refuse an input or an output that cannot fit with
// a message rather than stop with std::bad_alloc part-way.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <string>

#include <fmt/format.h>

namespace flotsam {

/// The bytes this process may hold: the machine's physical memory, or the address-space limit
/// (ulimit -v) when lower.
inline double usable_memory() {
  const double physical =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    return std::min(physical, static_cast<double>(limit.rlim_cur));
  return physical;
}

/// "1.8 GB", "640 MB".
inline std::string format_bytes(double bytes) {
  return bytes >= 1e9 ? fmt::format("{:.3g} GB", bytes / 1e9)
                      : fmt::format("{:.3g} MB", bytes / 1e6);
}

}  // namespace flotsam
