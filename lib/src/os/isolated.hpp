// arnoldweb: a piece of work on untrusted bytes tried first in a child process, so that a
// defect of a library it calls ends the child and not arnoldweb. The child is a fork of this
// process (no program is started, no shell: the work is a function of this one).
//
// Why: HDF5 1.10.8 (Debian 12's, and the wheel's) crashes, or reads past its buffers, on
// some damaged metadata, before it could return an error (tests/fuzz/hdf5-defects/; the
// fuzz target of saved runs found one more in CI on 2026-11-28). arnoldweb refuses what it
// can recognise before HDF5 opens a file (output/h5_heaps.hpp); the files it cannot vouch
// for — a state file, a map.h5 read back, the files handed to h5py — HDF5 reads first in a
// child, and then, the child having finished, in this process. HDF5 is deterministic: the
// same calls on the same bytes take the same paths, so what ended well in the child ends well
// here; the data are not carried back (no copy of a state file of gigabytes in a pipe).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace arnoldweb::detail {

// Runs `work` in a child process and returns once it has ended normally (`work` returned or
// threw: the caller then does the work in this process, where it throws the same). When the
// child ends in another way — killed by a signal, another exit status (a sanitizer's report),
// or not within `seconds` (it is then killed) — `died` is called with why ("killed by signal 11
// (Segmentation fault)", ...), and must throw. Returns at once, trying nothing, where no child
// can be made (fork fails) or ARNOLDWEB_HDF5_IN_PROCESS=1 is set (the fuzz targets' long
// search, which needs the coverage of what the child would run). Where this process's children
// are reaped as they end (SIGCHLD ignored, or SA_NOCLDWAIT) waitpid finds no status: the child
// then runs the work in a grandchild of its own and writes its status into a pipe instead.
void try_in_child(const std::function<void()>& work, const std::function<void(const std::string&)>& died,
                  int seconds);

// The time to allow a child reading `bytes` bytes: 120 s and 50 MB/s.
int seconds_for(std::uint64_t bytes);

}  // namespace arnoldweb::detail
