#pragma once
// For the fuzz targets that read HDF5 (include in the target's one .cpp).
// libhdf5 (Debian's 1.10.8) sizes its metadata-cache entries from the file:
// a malformed file makes it ask malloc for petabytes. With the allocator
// returning null, HDF5 fails the read (an InputError) instead of ASan
// aborting on a request tofsim never made.
extern "C" const char* __asan_default_options() { return "allocator_may_return_null=1"; }
