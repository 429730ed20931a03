#pragma once
// Reference fibre directions per element for one fibre family (doc/materials.md): a constant
// direction, a radial fan from a point (the genioglossus fans out from its mandibular
// attachment), or vectors read from a file, per element or per node. Fibres are axial, so N and
// -N are the same fibre: node vectors are aligned in sign before they are averaged over an
// element. Every direction returned is a unit vector; anything that would give a zero or
// undefined direction is an error naming the element (or the file and line).

#include <array>
#include <filesystem>
#include <vector>

#include <Eigen/Core>

#include "mesh/HexMesh.hpp"

namespace glossa::model {

// Throws std::invalid_argument for a zero direction.
std::vector<Eigen::Vector3d> constantDirections(const Eigen::Vector3d &direction, std::size_t count);

// The unit vector from `centre` to the point x, with its component along `planeNormal` removed
// when planeNormal is not zero (a fan lying in that plane). Throws std::invalid_argument when it
// is zero (x on the fan's centre or centre line).
Eigen::Vector3d radialFanDirection(const Eigen::Vector3d &x, const Eigen::Vector3d &centre,
                                   const Eigen::Vector3d &planeNormal);

// N_e = the unit vector from `centre` to the centroid of element e, with its component along
// `planeNormal` removed when planeNormal is not zero (a fan lying in that plane). Throws
// std::invalid_argument naming the element when the result is zero.
std::vector<Eigen::Vector3d> radialFanDirections(const mesh::HexMesh &mesh, const std::vector<mesh::ElementId> &elements,
                                                 const Eigen::Vector3d &centre, const Eigen::Vector3d &planeNormal);

// Fibre polylines: each a list of at least two vertices (reference positions).
using Polylines = std::vector<std::vector<Eigen::Vector3d>>;

// The unit direction of the polyline segment nearest to `x` (Euclidean distance from x to the
// closed segment; ties: the first in polyline, then segment, order). Sign convention: from a
// segment's first vertex to its second, i.e. in the order the polyline lists its vertices (a
// fibre is axial, so the sign has no mechanical meaning). Zero-length segments are skipped.
// Throws std::invalid_argument when there is no segment of positive length.
Eigen::Vector3d nearestSegmentDirection(const Polylines &polylines, const Eigen::Vector3d &x);

// N_e = nearestSegmentDirection(polylines, centroid of element e): one direction per element
// (the muscle architecture stores directions per element), the polyline segment nearest to the
// element's centroid (the mean of its 8 nodes). Throws std::invalid_argument as above.
std::vector<Eigen::Vector3d> polylineDirections(const mesh::HexMesh &mesh, const std::vector<mesh::ElementId> &elements,
                                                const Polylines &polylines);

// Per quadrature point (the tongue's polylines, doc/tongue.md): for each element, the direction of
// the segment nearest to each of its 8 Gauss points (the reference position x(xi_q) of
// fem::gaussHex2(), in that order). An element a fibre bends through, or that lies between two
// fibres, then carries the local direction at each point instead of one direction for all eight.
// Same sign convention and errors as nearestSegmentDirection.
using PointDirections = std::array<Eigen::Vector3d, 8>;
std::vector<PointDirections> polylinePointDirections(const mesh::HexMesh &mesh,
                                                     const std::vector<mesh::ElementId> &elements,
                                                     const Polylines &polylines);

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
