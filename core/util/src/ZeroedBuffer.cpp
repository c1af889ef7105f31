#include "tofsim/util/ZeroedBuffer.h"

#include <sys/mman.h>

#include <cstring>
#include <new>

namespace tofsim::util::detail {

void* mapZeroed(std::size_t bytes) {
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
    // Faulted in now, writable, in one call: an accumulator's first touch is a
    // read-modify-write, which would map the shared zero page and then copy it
    // on the write, two faults per page, in the middle of the gather.
#ifdef MADV_POPULATE_WRITE
  if (madvise(p, bytes, MADV_POPULATE_WRITE) == 0) return p;
#endif
  std::memset(p, 0, bytes);  // a kernel without it (before 5.14): the same by hand
  return p;
}

void unmap(void* p, std::size_t bytes) noexcept {
  if (p != nullptr) munmap(p, bytes);
}

}  // namespace tofsim::util::detail
