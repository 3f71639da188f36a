// arnoldweb: the one way HDF5 files are opened for reading (docs/reliability.md,
// "Reading HDF5 files"): state files (ensemble.file, states/state_file.cpp),
// map.h5 (saved_run.cpp: render, compare, Python's load) and the files that
// Python's arnoldweb.load hands to h5py (read_saved_hdf5_file). The policy:
//  - the file is a plain file (os/regular_file.hpp), opened through a name of
//    the very file that was checked, or from bytes already read;
//  - HDF5 is never allowed out of the file: every link on the way to a name
//    is looked at before the name is used (soft links are followed inside
//    the file, by this reader), and every dataset before its shape or data
//    is: external links, user-defined links, external raw storage and
//    virtual datasets are refused (they name other files, which may be FIFOs
//    or devices: a read would block for ever), and so are filters beyond
//    deflate, shuffle and fletcher32 (others load plugins). Before HDF5
//    opens the file, its heaps (global and local) are walked as HDF5 1.10.8 walks them
//    (a damaged one made HDF5 loop or take memory for ever: h5_heaps.hpp). A file handed to
//    another reader (h5py, which iterates groups) is first walked whole
//    (check_every_link). arnoldweb's own readers look names up rather than
//    iterate: HDF5 1.10.8 frees uninitialised entries of its link table when
//    a compact group's link count is damaged (found by the fuzzer under ASan);
//    a lookup builds no table;
//  - every dataset's data must be stored in the file: its storage is not
//    larger than the file, an unfiltered dataset's storage holds all its
//    bytes and a chunked one has every chunk written (HDF5 would otherwise
//    give fill values, and memory would follow the size the file declares,
//    not its size), and a deflated one inflates at most kMaxInflation times;
//  - attributes are read as h5py writes them: strings fixed or variable in
//    length, ASCII or UTF-8; numbers of one value.
// Every refusal goes to the caller's `fail` (its own error: StateError,
// SavedRunError), which must throw.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "os/isolated.hpp"
#include "os/regular_file.hpp"
#include "output/h5_heaps.hpp"
#include "output/hdf5_handle.hpp"

namespace arnoldweb::detail {

// object: "/momentum", "" for the file as a whole; message completes "<object> ...".
using H5Fail = std::function<void(const std::string& object, const std::string& message)>;

// deflate's largest ratio is 1032:1
constexpr std::uint64_t kMaxInflation = 1032;

class H5File {
 public:
  // `file` (checked and open) read from disk under the name `path`.
  H5File(const OpenPlainFile& file, const std::string& path, H5Fail fail);
  // `bytes`, read already from `path` (HDF5's in-memory driver); they must
  // outlive this object.
  H5File(std::string& bytes, const std::string& path, H5Fail fail);
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;

  hid_t id() const { return file_.id; }
  // Every link and dataset of the file by the policy (for a file that
  // another reader iterates).
  void check_every_link() const;
  // Whether `path` ("/final/momentum") names an object of the file.
  bool has(const std::string& path) const;
  // The dataset at `path`, open and checked (fail when it is none).
  H5Handle dataset(const std::string& path) const;
  // Its dimensions (fail when it has no simple shape).
  std::vector<hsize_t> dims(hid_t dataset, const std::string& path) const;

  bool has_attribute(const std::string& object, const char* name) const;
  // A string attribute (one value, fixed or variable length, ASCII or UTF-8).
  std::string text_attribute(const std::string& object, const char* name) const;
  // A number attribute (one value, an integer or a float of at most 8 bytes).
  double number_attribute(const std::string& object, const char* name) const;

  [[noreturn]] void fail(const std::string& object, const std::string& message) const;

 private:
  void open(const std::string& name, hid_t fapl);
  // fail for a heap on which HDF5 would loop or take memory for ever (h5_heaps.hpp)
  void guard_heaps(const ReadAt& read) const;
  // The path of hard links that `path` names ("/" the root), "" when it
  // names nothing; fail for a link on the way that leads out of the file.
  std::string resolve(const std::string& path, int hops) const;

  std::string path_;
  H5Fail fail_;
  std::uint64_t file_bytes_ = 0;
  // members, so that they are closed when a constructor fails
  H5Handle lapl_{-1, H5Pclose};  // link access that refuses external links (a second guard)
  H5Handle file_{-1, H5Fclose};
};

// "(3000, 3)", "()"
std::string show_shape(const std::vector<hsize_t>& dims);

// Why a file was refused when HDF5's reader of it, in a child process, died (`why`: how).
std::string hdf5_child_died(const std::string& why);

// `read` of a file of `bytes` bytes that arnoldweb cannot vouch for: done first in a child
// process (os/isolated.hpp), where a defect of HDF5's parser ends the child and `fail("", ...)`
// refuses the file, then here; returns what `read` returns here.
template <class Read>
auto read_in_child_first(std::uint64_t bytes, const H5Fail& fail, const Read& read) {
  try_in_child([&] { read(); }, [&](const std::string& why) { fail("", hdf5_child_died(why)); }, seconds_for(bytes));
  return read();
}

}  // namespace arnoldweb::detail
