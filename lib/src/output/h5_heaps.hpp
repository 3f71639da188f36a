// arnoldweb: a guard against two defects of HDF5 1.10.8 (Debian 12's, and the
// wheel's) in its readers of heaps, on which a damaged file never lets go:
// - a global heap collection whose free-space object has size 0: HDF5 loops
//   for ever (H5HG__cache_heap_deserialize advances by the object's size),
//   whatever reads it: a variable-length string attribute (h5py's strings), a
//   virtual dataset's mapping. Found by the fuzz target of state files on
//   2026-11-28 (tests/fuzz/hdf5-defects/global-heap-size-0, a mutation of an
//   h5py file with a virtual dataset); the reader before issue 37 blocked on it.
// - a local heap (a group's names) whose free list returns to a block it has
//   passed: HDF5 allocates a node per block it visits (H5HL__fl_deserialize)
//   until the memory is gone, at the first lookup of a name. Found by the fuzz
//   target of saved runs on 2026-11-28 (tests/fuzz/hdf5-defects/
//   local-heap-free-list-cycle, a mutation of an arnoldweb map.h5): 2 GB in
//   6 s under ASan.
//
// Before HDF5 opens a file, every place in its bytes that starts as a global
// heap collection ("GCOL") or a local heap ("HEAP") is walked as HDF5 walks
// it; a walk that would not end is the reason returned. Bytes of data that
// happen to read so are walked too: such a walk stops at the end of its heap,
// and it would fail to end only where HDF5's would (a chance of about 2^-16
// per accidental match, never for a heap HDF5 wrote).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace arnoldweb::detail {

// `read(offset, n)`: up to n bytes of the file from offset (fewer at its end).
using ReadAt = std::function<std::string(std::uint64_t offset, std::size_t n)>;

// "" or why HDF5 would not finish reading a heap of this file of `size` bytes.
std::string heap_problem(const ReadAt& read, std::uint64_t size);

}  // namespace arnoldweb::detail
