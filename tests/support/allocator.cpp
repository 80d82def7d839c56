// The test program keeps the memory a test frees for its next allocations, on the heap, instead of mapping
// blocks above 128 KB from the system and unmapping them when freed, whose pages then fault again when the
// next factor touches them. The quasi-static delamination paths (tests/analysis/thresholds/: UMFPACK's
// numeric factor on every correction) spent most of their time in those faults (perf: page faults under
// UMFPACK's allocation, memset and memmove). Measured on 2 cores beside another test run, 2026-12-04:
// DoubleCantileverBeam.* 36.5 and 33.6 s with glibc's defaults, 11.6 and 11.5 s with these settings (peak
// memory 97 and 104 MB); SeededDelaminationGrowth.* 125 s and 47 s (196 and 193 MB). The numbers a test
// checks do not depend on where a block lies. The sanitizer build keeps its own allocator.
#include <malloc.h>

namespace plyimpact::test {
namespace {

bool keep_freed_memory() {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
  constexpr int trim_above = 1 << 30; // return the heap's free top to the system above 1 GB only
  return mallopt(M_MMAP_MAX, 0) == 1 && mallopt(M_TRIM_THRESHOLD, trim_above) == 1; // every block on the heap
#else
  return false;
#endif
}

[[maybe_unused]] const bool kept = keep_freed_memory();

} // namespace
} // namespace plyimpact::test
