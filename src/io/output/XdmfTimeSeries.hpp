#pragma once
// The text of an XDMF 3 file describing a hexahedral mesh and its fields over time, with the
// heavy data in HDF5 files next to it (the mesh's, and each step's own or the mesh's). ParaView (Xdmf3 reader) opens it as a time series:
// a Temporal Collection with one Uniform grid per step, each repeating the same mesh
// datasets and listing that step's attributes. Pure text composition: no file access here.

#include <cstddef>
#include <string>
#include <vector>

namespace glossa::io {

enum class Centering { Node, Cell };

// One field of one step, stored in the HDF5 file as a dataset of shape (n) or (n, components).
struct XdmfAttribute {
  std::string name;
  int components;
  Centering center;
  std::string dataset; // absolute path inside the HDF5 file, e.g. "/step_000000/displacement"
};

struct XdmfStep {
  double time;
  std::vector<XdmfAttribute> attributes;
  // The HDF5 file of this step's attributes, relative to the XDMF file; empty: the mesh's.
  std::string heavyDataFile = {};
};

// Where the mesh lives: coordinates (numNodes x 3 float64), topology (numCells x 8 int64, VTK
// hexahedron node order), both in `heavyDataFile` (a path relative to the XDMF file).
struct XdmfMesh {
  std::string heavyDataFile;
  std::size_t numNodes;
  std::size_t numCells;
  std::string coordinatesDataset;
  std::string topologyDataset;
};

// The XDMF AttributeType for a tuple size: "Scalar" (1), "Vector" (3), "Tensor6" (6),
// "Tensor" (9); nullptr for any other size.
const char *xdmfAttributeType(int components);

// With no steps the document holds just the mesh (a lone Uniform grid), so the mesh can be
// inspected before the first step is written.
std::string composeXdmfTimeSeries(const XdmfMesh &mesh, const std::vector<XdmfStep> &steps);

} // namespace glossa::io
