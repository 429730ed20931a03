#include "io/output/ResultWriter.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <hdf5.h>

namespace glossa::io {

namespace {
void check(herr_t status, const std::string &what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

void writeDataset(hid_t parent, const std::string &name, hid_t type, const void *data, hsize_t rows, hsize_t cols) {
  const hsize_t dims[2] = {rows, cols};
  const hid_t space = H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr);
  const hid_t set = H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) throw std::runtime_error("HDF5: cannot create dataset " + name);
  check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "writing " + name);
  H5Dclose(set);
  H5Sclose(space);
}

const char *attributeType(int components) {
  switch (components) {
  case 1: return "Scalar";
  case 3: return "Vector";
  case 6: return "Tensor6";
  case 9: return "Tensor";
  }
  return nullptr;
}
} // namespace

ResultWriter::ResultWriter(const std::filesystem::path &directory, const std::string &baseName,
                           const std::vector<Eigen::Vector3d> &nodes,
                           const std::vector<std::array<std::int64_t, 8>> &hexes)
    : directory_(directory), baseName_(baseName), numNodes_(nodes.size()), numCells_(hexes.size()) {
  std::filesystem::create_directories(directory_);
  const std::string path = (directory_ / (baseName_ + ".h5")).string();
  file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error("cannot create " + path);
  const hid_t mesh = H5Gcreate2(file_, "mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<double> xyz;
  xyz.reserve(3 * nodes.size());
  for (const auto &x : nodes) xyz.insert(xyz.end(), {x.x(), x.y(), x.z()});
  writeDataset(mesh, "coordinates", H5T_NATIVE_DOUBLE, xyz.data(), numNodes_, 3);
  writeDataset(mesh, "topology", H5T_NATIVE_INT64, hexes.data(), numCells_, 8);
  H5Gclose(mesh);
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush");
  writeXdmf();
}

ResultWriter::~ResultWriter() {
  if (file_ >= 0) H5Fclose(file_);
}

void ResultWriter::writeStep(double time, const std::vector<Field> &nodeFields, const std::vector<Field> &cellFields) {
  StepRecord record{time, "step_" + std::to_string(steps_.size()), {}};
  auto validate = [](const Field &f, std::size_t n, const char *where) {
    if (!attributeType(f.components))
      throw std::invalid_argument("field '" + f.name + "': " + std::to_string(f.components) +
                                  " components (1, 3, 6 or 9 allowed)");
    if (f.values.size() != n * static_cast<std::size_t>(f.components))
      throw std::invalid_argument("field '" + f.name + "' has " + std::to_string(f.values.size()) + " values, " +
                                  where + " needs " + std::to_string(n * f.components));
  };
  for (const auto &f : nodeFields) validate(f, numNodes_, "a node field");
  for (const auto &f : cellFields) validate(f, numCells_, "a cell field");

  const hid_t group = H5Gcreate2(file_, record.group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(group, "time", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, H5T_NATIVE_DOUBLE, &time);
  H5Aclose(attr);
  H5Sclose(space);
  for (const auto &f : nodeFields) {
    writeDataset(group, f.name, H5T_NATIVE_DOUBLE, f.values.data(), numNodes_, f.components);
    record.fields.push_back({Field{f.name, f.components, {}}, true});
  }
  for (const auto &f : cellFields) {
    writeDataset(group, f.name, H5T_NATIVE_DOUBLE, f.values.data(), numCells_, f.components);
    record.fields.push_back({Field{f.name, f.components, {}}, false});
  }
  H5Gclose(group);
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush");
  steps_.push_back(std::move(record));
  writeXdmf();
}

void ResultWriter::writeXdmf() const {
  const std::string h5 = baseName_ + ".h5";
  std::ostringstream x;
  x.precision(17);
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n"
    << "<Grid Name=\"time series\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  auto grid = [&](double time, const StepRecord *step) {
    x << "  <Grid Name=\"mesh\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << time << "\"/>\n"
      << "    <Topology TopologyType=\"Hexahedron\" NumberOfElements=\"" << numCells_ << "\">\n"
      << "      <DataItem Dimensions=\"" << numCells_ << " 8\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">"
      << h5 << ":/mesh/topology</DataItem>\n    </Topology>\n"
      << "    <Geometry GeometryType=\"XYZ\">\n"
      << "      <DataItem Dimensions=\"" << numNodes_ << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
      << h5 << ":/mesh/coordinates</DataItem>\n    </Geometry>\n";
    if (step)
      for (const auto &[f, isNode] : step->fields) {
        const std::size_t n = isNode ? numNodes_ : numCells_;
        x << "    <Attribute Name=\"" << f.name << "\" AttributeType=\"" << attributeType(f.components)
          << "\" Center=\"" << (isNode ? "Node" : "Cell") << "\">\n"
          << "      <DataItem Dimensions=\"" << n << (f.components > 1 ? " " + std::to_string(f.components) : "")
          << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":/" << step->group << "/" << f.name
          << "</DataItem>\n    </Attribute>\n";
      }
    x << "  </Grid>\n";
  };
  if (steps_.empty()) grid(0.0, nullptr);
  for (const auto &s : steps_) grid(s.time, &s);
  x << "</Grid>\n</Domain>\n</Xdmf>\n";

  const auto target = directory_ / (baseName_ + ".xdmf");
  const auto temporary = directory_ / (baseName_ + ".xdmf.tmp");
  {
    std::ofstream out(temporary);
    out << x.str();
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, target);
}

} // namespace glossa::io
