// arnoldweb: a piece of work on untrusted bytes done in a child process, so that a defect
// of a library it calls ends the child and not arnoldweb. The child is a fork of this
// process (no program is started, no shell: the work is a function of this one); what it
// returns comes back through a pipe.
//
// Why: HDF5 1.10.8 (Debian 12's, and the wheel's) crashes, or reads past its buffers, on
// some damaged metadata, before it could return an error (tests/fuzz/hdf5-defects/; the
// fuzz target of saved runs found one more in CI on 2026-11-28). arnoldweb refuses what it
// can recognise before HDF5 opens a file (output/h5_heaps.hpp), and reads the files it
// cannot vouch for — a map.h5 read back, the files handed to h5py — in a child: a crash
// there is a clear error naming the file, and the run, render or Python session goes on.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace arnoldweb::detail {

// Runs `work` in a child process and returns what it returned. `work` reports the
// errors it expects in the string it returns (its caller decodes them); an exception it
// lets out comes back as std::runtime_error with its what() (an unexpected one). When the
// child ends in another way — killed by a signal, an exit without an answer (a sanitizer's
// report), or no answer within `seconds` (it is then killed) — `died` is called with why
// ("killed by signal 11 (Segmentation fault)", ...), and must throw. Where no child can be
// made (fork fails), `work` runs in this process.
std::string run_isolated(const std::function<std::string()>& work, const std::function<void(const std::string&)>& died,
                         int seconds = 120);

// Whether run_isolated makes a child: yes, unless ARNOLDWEB_HDF5_IN_PROCESS=1 is set (the
// fuzz targets' long search, which needs the coverage of what the child would run).
bool isolating();

// An answer's bytes: numbers, strings and arrays of numbers, one after the other, in this
// machine's byte order (parent and child are one program).
class Packer {
 public:
  template <class T>
  Packer& put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
    return *this;
  }
  template <class T>
  Packer& put(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    return *this;
  }
  Packer& put(const std::string& s) {
    put<std::uint64_t>(s.size());
    bytes += s;
    return *this;
  }
  std::string bytes;
};

// Reads back what a Packer wrote, in the same order (std::runtime_error where it ends early).
class Unpacker {
 public:
  explicit Unpacker(const std::string& bytes, std::size_t at = 0) : b_(bytes), at_(at) {}
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  template <class T>
  std::vector<T> array() {
    const auto n = get<std::uint64_t>();
    if (n > (b_.size() - at_) / sizeof(T)) throw std::runtime_error("an isolated reader's answer ends early");
    std::vector<T> v(n);
    if (n) std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
    return v;
  }
  std::string text() {
    const auto n = get<std::uint64_t>();
    if (n > b_.size() - at_) throw std::runtime_error("an isolated reader's answer ends early");
    return std::string(take(n), n);
  }

 private:
  const char* take(std::size_t n) {
    if (n > b_.size() - at_) throw std::runtime_error("an isolated reader's answer ends early");
    at_ += n;
    return b_.data() + at_ - n;
  }
  const std::string& b_;
  std::size_t at_;
};

}  // namespace arnoldweb::detail
