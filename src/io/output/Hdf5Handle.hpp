#pragma once
// Owns one HDF5 identifier (file, group, dataset, dataspace, attribute) and closes it on scope
// exit, so an exception thrown half-way through a write leaks nothing. Internal to the output
// writers; includes <hdf5.h>, so keep it out of public headers.

#include <stdexcept>
#include <string>
#include <utility>

#include <hdf5.h>

#include "io/output/OutputError.hpp"

namespace glossa::io {

class Hdf5Handle {
public:
  using Closer = herr_t (*)(hid_t);

  // Throws std::runtime_error mentioning `what` when the HDF5 call that produced `id` failed.
  Hdf5Handle(hid_t id, Closer close, const std::string &what) : id_(id), close_(close) {
    if (id_ < 0) throw OutputError("HDF5: " + what + " failed");
  }
  ~Hdf5Handle() {
    if (id_ >= 0) close_(id_);
  }
  Hdf5Handle(const Hdf5Handle &) = delete;
  Hdf5Handle &operator=(const Hdf5Handle &) = delete;
  Hdf5Handle(Hdf5Handle &&other) noexcept : id_(std::exchange(other.id_, -1)), close_(other.close_) {}
  Hdf5Handle &operator=(Hdf5Handle &&) = delete;

  hid_t get() const { return id_; }
  // Hands ownership to the caller (who must close it).
  hid_t release() { return std::exchange(id_, -1); }

private:
  hid_t id_;
  Closer close_;
};

// For HDF5 calls that return a status instead of an identifier.
inline void checkHdf5(herr_t status, const std::string &what) {
  if (status < 0) throw OutputError("HDF5: " + what + " failed");
}

} // namespace glossa::io
