#include "core/resources.hpp"

#include <sys/resource.h>

namespace fest {

long peak_rss_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

}  // namespace fest
