#pragma once
// Reference nodal coordinates stored in a file (doc/tongue.md): the zero-strain configuration
// computed by `glossa zero-strain` and reused by later runs through the deck's
// Mesh/reference coordinates file. The mesh keeps its connectivity, sets and labels; only the
// node positions change, so F_RI (eq. 1) is implied by the change of coordinates.
//
// Format: plain text, one node a line, "node x y z" with node the 0-based index of the node in
// the mesh as the deck builds it (after refinement), coordinates in metres, separated by spaces,
// tabs or commas. Blank lines and lines starting with '#' are comments. Every node appears
// exactly once, in any order.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// Makes `reference` the mesh's node positions and keeps the positions as they were (the imaged
// geometry) in imagedNodes. Everything selected by geometry (face sets, named points, fibre
// directions) stays a label of the imaged anatomy; named points move with their nodes (a probe
// keeps its local coordinates in its element's new shape). `reference` has one entry per node.
void replaceReferenceNodes(HexMesh &m, std::vector<Eigen::Vector3d> reference);

// Reads the file for a mesh of `numNodes` nodes. Throws std::runtime_error with "FILE:LINE:"
// for a malformed line, a node index out of range, a repeated node or a non-finite value, and
// "FILE:" for a missing file or a node count that differs from the mesh's.
std::vector<Eigen::Vector3d> readReferenceCoordinates(const std::string &path, std::size_t numNodes);

// The number of node lines in the file (comments and blank lines not counted), to tell a file
// for the mesh as read from one for its refinement. Throws std::runtime_error if it cannot be read.
std::size_t countReferenceCoordinates(const std::string &path);

// Writes the nodes in this format; `header` lines are written as '#' comments first. Throws
// std::runtime_error if the file cannot be written.
void writeReferenceCoordinates(const std::string &path, const std::vector<Eigen::Vector3d> &nodes,
                               const std::vector<std::string> &header = {});

}  // namespace glossa::mesh
