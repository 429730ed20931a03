#pragma once
// Reading back what ResultWriter wrote, with the plain HDF5 C API, independently of the writer's
// own code: datasets with their shapes, the "time" attribute of a step, and the list of all
// datasets in a file (to compare with what the XDMF file references).

#include <cstdint>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <hdf5.h>

namespace glossa::io::testing {

template <typename T> struct Dataset {
  std::vector<hsize_t> dims;
  std::vector<T> values;
};

class Hdf5File {
public:
  explicit Hdf5File(const std::filesystem::path &path)
      : id_(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {
    if (id_ < 0) throw std::runtime_error("cannot open " + path.string());
  }
  ~Hdf5File() { H5Fclose(id_); }
  Hdf5File(const Hdf5File &) = delete;
  Hdf5File &operator=(const Hdf5File &) = delete;

  Dataset<double> doubles(const std::string &path) const { return read<double>(path, H5T_NATIVE_DOUBLE); }
  Dataset<std::int64_t> int64s(const std::string &path) const { return read<std::int64_t>(path, H5T_NATIVE_INT64); }

  bool hasLink(const std::string &path) const {
    htri_t exists = 0;
    H5E_BEGIN_TRY { exists = H5Lexists(id_, path.c_str(), H5P_DEFAULT); }
    H5E_END_TRY;
    return exists > 0;
  }

  double timeOf(const std::string &group) const {
    const hid_t attribute = H5Aopen_by_name(id_, group.c_str(), "time", H5P_DEFAULT, H5P_DEFAULT);
    if (attribute < 0) throw std::runtime_error("no time attribute on " + group);
    double time = 0.0;
    H5Aread(attribute, H5T_NATIVE_DOUBLE, &time);
    H5Aclose(attribute);
    return time;
  }

  // Absolute paths ("/mesh/coordinates", ...) of every dataset in the file.
  std::set<std::string> datasetPaths() const {
    std::set<std::string> paths;
    H5Lvisit(id_, H5_INDEX_NAME, H5_ITER_NATIVE, &collectDataset, &paths);
    return paths;
  }

private:
  template <typename T> Dataset<T> read(const std::string &path, hid_t type) const {
    const hid_t set = H5Dopen2(id_, path.c_str(), H5P_DEFAULT);
    if (set < 0) throw std::runtime_error("no dataset " + path);
    const hid_t space = H5Dget_space(set);
    Dataset<T> out;
    out.dims.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, out.dims.data(), nullptr);
    out.values.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    const herr_t status = H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data());
    H5Sclose(space);
    H5Dclose(set);
    if (status < 0) throw std::runtime_error("cannot read " + path);
    return out;
  }

  // H5Lvisit and H5Iget_type keep their signatures across HDF5 1.10 - 1.14 (H5Ovisit does not).
  static herr_t collectDataset(hid_t group, const char *name, const H5L_info_t *, void *paths) {
    const hid_t object = H5Oopen(group, name, H5P_DEFAULT);
    if (object < 0) return -1;
    if (H5Iget_type(object) == H5I_DATASET)
      static_cast<std::set<std::string> *>(paths)->insert("/" + std::string(name));
    H5Oclose(object);
    return 0;
  }

  hid_t id_;
};

} // namespace glossa::io::testing
