#include "app/resources/heap_trim.hpp"

#include <cstdlib> // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace grainload::app {

void keep_freed_heap() {
#if defined(__GLIBC__)
    mallopt(M_TRIM_THRESHOLD, kHeapTrimThreshold);
#endif
}

} // namespace grainload::app
