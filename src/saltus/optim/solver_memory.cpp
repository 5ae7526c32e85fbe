#include "saltus/optim/solver_memory.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace saltus {

void keep_solver_memory_in_heap() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace saltus
