#pragma once
// HDF5 prints its whole error stack to stderr on every failed call by default. Our callers
// turn each failure into a grainbridge::Error that names the file and dataset, so the stack
// is noise (and probing for an optional dataset would print one). This switches printing
// off for a scope and restores whatever the process had before.
#include <hdf5.h>

namespace grainbridge::core::io {

class H5ErrorSilencer {
 public:
  H5ErrorSilencer() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~H5ErrorSilencer() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  H5ErrorSilencer(const H5ErrorSilencer&) = delete;
  H5ErrorSilencer& operator=(const H5ErrorSilencer&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

}  // namespace grainbridge::core::io
