#include "io/output/ResultWriter.hpp"

#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <type_traits>

#include "io/output/AtomicFile.hpp"
#include "io/output/Hdf5Handle.hpp"
#include "io/output/OutputError.hpp"
#include "io/output/RoundTripText.hpp"

namespace glossa::io {

static_assert(std::is_same_v<hid_t, std::int64_t>, "ResultWriter stores the HDF5 file id as std::int64_t");

namespace {
// A dataset of shape (rows) for one component, else (rows, columns), written in one call with
// default property lists (contiguous layout: the data goes straight to the file).
void writeDataset(hid_t parent, const std::string &name, hid_t memoryType, const void *data, hsize_t rows,
                  hsize_t columns) {
  const hsize_t dims[2] = {rows, columns};
  const Hdf5Handle space(H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr), H5Sclose,
                         "creating the dataspace of " + name);
  const Hdf5Handle set(
      H5Dcreate2(parent, name.c_str(), memoryType, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
      "creating dataset " + name);
  // H5Dwrite with an empty selection is fine, but some HDF5 builds reject a null buffer.
  if (rows * columns > 0)
    checkHdf5(H5Dwrite(set.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "writing dataset " + name);
}

void writeTimeAttribute(hid_t group, double time) {
  const Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose, "creating a scalar dataspace");
  const Hdf5Handle attribute(H5Acreate2(group, "time", H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                             H5Aclose, "creating attribute time");
  checkHdf5(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &time), "writing attribute time");
}

// "step_000042": zero-padded so the groups sort in time order in h5dump and h5py.
std::string stepGroupName(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "step_%06zu", index);
  return name;
}

void checkBaseName(const std::string &baseName) {
  // ':' separates file and dataset in an XDMF DataItem; '/' would put the files elsewhere.
  if (baseName.empty() || baseName.find_first_of("/:\\") != std::string::npos)
    throw std::invalid_argument("ResultWriter: base name '" + baseName +
                                "' must be a plain file name (no '/', '\\' or ':')");
}

void checkTopology(const std::vector<std::array<std::int64_t, 8>> &hexes, std::size_t numNodes) {
  for (std::size_t e = 0; e < hexes.size(); ++e)
    for (const std::int64_t node : hexes[e])
      if (node < 0 || static_cast<std::size_t>(node) >= numNodes)
        throw std::invalid_argument("ResultWriter: hexahedron " + std::to_string(e) + " names node " +
                                    std::to_string(node) + " but the mesh has " + std::to_string(numNodes) +
                                    " nodes");
}
// File access without HDF5's file locks (a restart's read of the mesh file): ParaView 5.11 (HDF5
// 1.10) aborted on the lock of a running job's file unless the user set
// HDF5_USE_FILE_LOCKING=FALSE. Readers still take their own locks; the writer ignores them.
Hdf5Handle unlockedAccess() {
  Hdf5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "creating a file access property list");
  checkHdf5(H5Pset_file_locking(fapl.get(), false, true), "turning off HDF5 file locking");
  return fapl;
}

// A file is built in memory (HDF5's core driver without a backing store) and its image written
// to disk by replaceFileAtomically, whose every write is checked: HDF5 never meets a full disk.
// When it did, a failed flush left the file open inside HDF5, and closing it again at
// MPI_Finalize (H5F__close_cb) crashed the run that should have ended with exit status 4.
// Nothing holds a file on disk open, so no file lock is taken either.
Hdf5Handle createInMemory(const std::string &name) {
  const Hdf5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "creating a file access property list");
  checkHdf5(H5Pset_fapl_core(fapl.get(), 1 << 20, false), "choosing HDF5's in-memory driver");
  return Hdf5Handle(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose,
                    "creating " + name + " in memory");
}

// The bytes of an in-memory file, as they would be on disk.
std::string fileImage(hid_t file, const std::string &name) {
  checkHdf5(H5Fflush(file, H5F_SCOPE_GLOBAL), "flushing " + name + " in memory");
  const ssize_t size = H5Fget_file_image(file, nullptr, 0);
  if (size < 0) throw OutputError("HDF5: sizing the image of " + name + " failed");
  std::string image(static_cast<std::size_t>(size), '\0');
  if (H5Fget_file_image(file, image.data(), image.size()) != size)
    throw OutputError("HDF5: copying the image of " + name + " failed");
  return image;
}
// Tuples of (xx, yy, zz, xy, yz, xz) as row-major 3x3 tensors.
std::vector<double> fullSymmetricTensors(const std::vector<double> &six) {
  std::vector<double> full;
  full.reserve(six.size() / 6 * 9);
  for (std::size_t t = 0; t + 6 <= six.size(); t += 6) {
    const double xx = six[t], yy = six[t + 1], zz = six[t + 2], xy = six[t + 3], yz = six[t + 4], xz = six[t + 5];
    full.insert(full.end(), {xx, xy, xz, xy, yy, yz, xz, yz, zz});
  }
  return full;
}
} // namespace

ResultWriter::ResultWriter(const std::filesystem::path &directory, const std::string &baseName,
                           const std::vector<Eigen::Vector3d> &nodes,
                           const std::vector<std::array<std::int64_t, 8>> &hexes)
    : directory_(directory), baseName_(baseName),
      mesh_{baseName + ".h5", nodes.size(), hexes.size(), "/mesh/coordinates", "/mesh/topology"} {
  checkBaseName(baseName_);
  checkTopology(hexes, nodes.size());
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // failures are reported as OutputError, not HDF5's dump
  std::filesystem::create_directories(directory_);

  // An XDMF file from an earlier run would point into the .h5 we are about to replace; remove it
  // first so that no moment exists at which it names missing data. Unlinking the old .h5 (instead
  // of truncating it) leaves a ParaView that still has it open reading intact old data.
  std::filesystem::remove(xdmfPath());
  std::filesystem::remove(hdf5Path());
  std::filesystem::remove_all(stepsDirectory());
  std::filesystem::create_directories(stepsDirectory());

  std::string image;
  {
    const Hdf5Handle file = createInMemory(hdf5Path().string());
    const Hdf5Handle mesh(H5Gcreate2(file.get(), "mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                          "creating group /mesh");
    std::vector<double> xyz;
    xyz.reserve(3 * nodes.size());
    for (const auto &x : nodes) xyz.insert(xyz.end(), {x.x(), x.y(), x.z()});
    writeDataset(mesh.get(), "coordinates", H5T_NATIVE_DOUBLE, xyz.data(), nodes.size(), 3);
    // std::array<int64_t, 8> is contiguous and unpadded, so the vector is already E x 8 row-major.
    static_assert(sizeof(std::array<std::int64_t, 8>) == 8 * sizeof(std::int64_t));
    writeDataset(mesh.get(), "topology", H5T_NATIVE_INT64, hexes.data(), hexes.size(), 8);
    image = fileImage(file.get(), hdf5Path().string());
  }
  replaceFileAtomically(hdf5Path(), image);
  writeXdmf();
}

ResultWriter::ResultWriter(const std::filesystem::path &directory, const std::string &baseName, std::size_t numNodes,
                           std::size_t numCells, std::vector<XdmfStep> resumeSteps)
    : directory_(directory), baseName_(baseName),
      mesh_{baseName + ".h5", numNodes, numCells, "/mesh/coordinates", "/mesh/topology"}, steps_(std::move(resumeSteps)) {
  checkBaseName(baseName_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  {
    const Hdf5Handle file(H5Fopen(hdf5Path().c_str(), H5F_ACC_RDONLY, unlockedAccess().get()), H5Fclose,
                          "opening " + hdf5Path().string() + " to resume it");
  }
  for (std::size_t k = 0; k < steps_.size(); ++k) {
    steps_[k].heavyDataFile = stepFile(k);
    if (!std::filesystem::exists(directory_ / stepFile(k)))
      throw OutputError((directory_ / stepFile(k)).string() + ": missing; the run cannot resume at its checkpoint");
  }
  // Steps written after the checkpoint are written again by the restarted run; a step file the
  // kill cut short goes too (staged as .tmp by replaceFileAtomically; .part by earlier versions).
  for (std::size_t k = steps_.size(); std::filesystem::exists(directory_ / stepFile(k)); ++k)
    std::filesystem::remove(directory_ / stepFile(k));
  for (const auto &entry : std::filesystem::directory_iterator(stepsDirectory()))
    if (entry.path().extension() == ".tmp" || entry.path().extension() == ".part") std::filesystem::remove(entry.path());
  writeXdmf();
}

ResultWriter::~ResultWriter() = default;

void ResultWriter::checkStep(double time, const std::vector<Field> &nodeFields,
                             const std::vector<Field> &cellFields) const {
  if (!std::isfinite(time)) throw std::invalid_argument("ResultWriter: step time is not finite");
  if (!steps_.empty() && !(time > steps_.back().time))
    throw std::invalid_argument("ResultWriter: step time " + roundTripText(time) +
                                " is not after the previous step's " + roundTripText(steps_.back().time));
  std::set<std::string> names; // node and cell fields share the step's group
  auto check = [&](const Field &f, std::size_t tuples, const char *kind) {
    const std::string which = std::string("ResultWriter: ") + kind + " field '" + f.name + "'";
    if (f.name.empty() || f.name == "." || f.name.find('/') != std::string::npos)
      throw std::invalid_argument(which + ": a name must be non-empty, not '.', and contain no '/'");
    if (!names.insert(f.name).second)
      throw std::invalid_argument(which + ": another field of this step has the same name");
    if (!xdmfAttributeType(f.components))
      throw std::invalid_argument(which + " has " + std::to_string(f.components) +
                                  " components; 1, 3, 6 or 9 are allowed");
    const std::size_t expected = tuples * static_cast<std::size_t>(f.components);
    if (f.values.size() != expected)
      throw std::invalid_argument(which + " has " + std::to_string(f.values.size()) + " values; " +
                                  std::to_string(tuples) + " x " + std::to_string(f.components) + " = " +
                                  std::to_string(expected) + " expected");
  };
  for (const auto &f : nodeFields) check(f, mesh_.numNodes, "node");
  for (const auto &f : cellFields) check(f, mesh_.numCells, "cell");
}

void ResultWriter::writeStep(double time, const std::vector<Field> &nodeFields,
                             const std::vector<Field> &cellFields) {
  checkStep(time, nodeFields, cellFields);
  const std::size_t index = steps_.size();
  const std::string group = stepGroupName(index);
  XdmfStep step{time, {}, stepFile(index)};
  // The step's own file, replaced into place whole (replaceFileAtomically): a reader (ParaView on a
  // running job) sees either no file or the whole step, and never a file that is being changed (a
  // reader of one file the writer appends to met its metadata in flux).
  const std::filesystem::path final = directory_ / step.heavyDataFile;
  std::string image;
  {
    const Hdf5Handle file = createInMemory(final.string());
    const Hdf5Handle g(H5Gcreate2(file.get(), group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                       "creating group /" + group);
    writeTimeAttribute(g.get(), time);
    auto write = [&](const Field &f, std::size_t tuples, Centering center) {
      if (f.components == 6) { // a symmetric tensor is written whole: see ResultWriter.hpp
        const std::vector<double> full = fullSymmetricTensors(f.values);
        writeDataset(g.get(), f.name, H5T_NATIVE_DOUBLE, full.data(), tuples, 9);
        step.attributes.push_back({f.name, 9, center, "/" + group + "/" + f.name});
        return;
      }
      writeDataset(g.get(), f.name, H5T_NATIVE_DOUBLE, f.values.data(), tuples, f.components);
      step.attributes.push_back({f.name, f.components, center, "/" + group + "/" + f.name});
    };
    for (const auto &f : nodeFields) write(f, mesh_.numNodes, Centering::Node);
    for (const auto &f : cellFields) write(f, mesh_.numCells, Centering::Cell);
    image = fileImage(file.get(), final.string());
  }
  // Nothing of a step that fails here stays: the XDMF file still describes the previous steps only.
  replaceFileAtomically(final, image);
  steps_.push_back(std::move(step));
  try {
    writeXdmf();
  } catch (...) {
    // The XDMF file still names the previous steps only: their files alone stay.
    steps_.pop_back();
    std::error_code ignored;
    std::filesystem::remove(final, ignored);
    throw;
  }
}

std::filesystem::path ResultWriter::stepsDirectory() const { return directory_ / (baseName_ + "_steps"); }

std::string ResultWriter::stepFile(std::size_t index) const {
  return baseName_ + "_steps/" + stepGroupName(index) + ".h5";
}

void ResultWriter::writeXdmf() const {
  replaceFileAtomically(xdmfPath(), composeXdmfTimeSeries(mesh_, steps_));
}

} // namespace glossa::io
