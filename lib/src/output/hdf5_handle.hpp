// arnoldweb: an HDF5 handle for the readers (saved_run.cpp, states/state_file.cpp),
// closed with its own close function on every path out.
#pragma once

#include <hdf5.h>

namespace arnoldweb {

struct H5Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  ~H5Handle() {
    if (id >= 0) close(id);
  }
};

}  // namespace arnoldweb
