#pragma once
// Reference fibre directions per element for one fibre family (issue 3, item 2): a constant
// direction, a radial fan from a point (the genioglossus fans out from its mandibular
// attachment), or vectors read from a file, per element or per node. Fibres are axial, so N and
// -N are the same fibre: node vectors are aligned in sign before they are averaged over an
// element. Every direction returned is a unit vector; anything that would give a zero or
// undefined direction is an error naming the element (or the file and line).

#include <filesystem>
#include <vector>

#include <Eigen/Core>

#include "mesh/HexMesh.hpp"

namespace glossa::model {

// Throws std::invalid_argument for a zero direction.
std::vector<Eigen::Vector3d> constantDirections(const Eigen::Vector3d &direction, std::size_t count);

// N_e = the unit vector from `centre` to the centroid of element e, with its component along
// `planeNormal` removed when planeNormal is not zero (a fan lying in that plane). Throws
// std::invalid_argument naming the element when the result is zero.
std::vector<Eigen::Vector3d> radialFanDirections(const mesh::HexMesh &mesh, const std::vector<mesh::ElementId> &elements,
                                                 const Eigen::Vector3d &centre, const Eigen::Vector3d &planeNormal);

enum class DirectionsPer { Element, Node };

// A text file of lines "id nx ny nz" (separated by spaces, tabs or commas; '#' starts a comment;
// ids are the mesh's 0-based element or node numbers). Every element of `elements` (or every
// node of those elements) must have a non-zero vector. Throws std::runtime_error naming the file
// and line for a malformed line, an id out of range, a repeated id or a zero vector, and the
// first element left without a direction.
std::vector<Eigen::Vector3d> directionsFromFile(const std::filesystem::path &file, DirectionsPer per,
                                                const mesh::HexMesh &mesh,
                                                const std::vector<mesh::ElementId> &elements);

} // namespace glossa::model
