#pragma once
// Reader for ANSYS node/element lists and the APDL macros of the ICP/GIPSA tongue
// (data/artisynth-tongue3d/README.md): element components (CreateMuscles.mac), fibre polylines
// (Fibers.mac) and plain lists of node ids (jaw and hyoid attachments). doc/meshes.md describes
// the formats, the quirks accepted and the errors.

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "mesh/ImportedMesh.hpp"

namespace glossa::mesh {

// `nodeFile`: one node per line, "id x y z". `elementFile`: one SOLID185-style hexahedron per
// line, "I J K L M N O P MAT TYPE REAL SECNUM ESYS id" (14 integers). ANSYS's I J K L M N O P
// order is VTK's 0..7 order (I J K L the bottom face counter-clockwise seen from the top face),
// so nodes are copied in order; every element must then have det(dX/dxi) > 0 at its Gauss
// points, otherwise it is refused as inverted. Ids may be any distinct integers; Glossa numbers
// nodes and elements 0.. in file order and keeps the file ids in the result.
// Throws std::runtime_error "file:line: reason".
ImportedMesh readAnsysMesh(const std::string &nodeFile, const std::string &elementFile);

// The element components of an APDL macro.
struct AnsysComponents {
  std::vector<std::string> names;            // non-empty components, in the order of their CM commands
  std::vector<std::string> emptyComponents;  // CM of an empty selection
  std::map<std::string, std::vector<std::string>> groups;  // CMGRP,name,member,...
  std::vector<std::string> declaredNames;                  // muscleName(i) = '...', by i
};

// Executes the element selection commands of the macro: ESEL,S|A|U|R,ELEM,,a[,b[,inc]],
// ESEL,ALL, ESEL,NONE, CM,name,ELEM, CMGRP,name,members..., and the muscleName(i) = 'X'
// array. Each non-empty component becomes an element set of `imported.mesh` (0-based ids).
// If muscleName(i) is declared, the i-th CM must carry that name (the README's rule that the
// k-th CM belongs to the k-th name is checked, not assumed). Lines starting with '*' or '/'
// and scalar assignments are declarations without effect on the sets and are skipped; any
// other command is refused rather than ignored, since skipping a selection would silently
// give wrong sets.
AnsysComponents readAnsysComponents(const std::string &macroFile, ImportedMesh &imported);

// One vertex of a fibre polyline: a mesh node, or an external anchor (node == -1) whose
// position the caller supplied.
struct FibrePoint {
  NodeId node;          // 0-based mesh node, or -1 for an external point
  std::int64_t fileId;  // the id in the macro
  Eigen::Vector3d position;
};

struct MuscleFibres {
  std::string muscle;
  std::vector<std::vector<FibrePoint>> fibres;  // each with at least two points
};

// FIBER(k,f,m) = n (k-th node of fibre f of muscle m), NB_NODES_FIBER(f,m), NB_FIBERS(m).
// Muscle m is muscleNames[m-1]. Node ids that are not mesh nodes must be keys of
// externalPoints (the tongue's styloid anchors 4037 and 4042), else the line is refused.
// The counts must agree with the FIBER entries (no gaps, no missing fibres).
std::vector<MuscleFibres> readAnsysFibres(const std::string &fibreFile, const ImportedMesh &imported,
                                          const std::vector<std::string> &muscleNames,
                                          const std::map<std::int64_t, Eigen::Vector3d> &externalPoints);

// A list of node ids separated by white space (any number per line, '!' or '#' comments)
// becomes node set `setName` of imported.mesh (sorted, unique).
void readAnsysNodeList(const std::string &file, const std::string &setName, ImportedMesh &imported);

// The files of an ANSYS model with components, fibres and attachment node lists.
struct AnsysModelFiles {
  std::string nodes;
  std::string elements;
  std::string components;                       // optional ("" = none)
  std::string fibres;                           // optional; needs components for the muscle names
  std::map<std::string, std::string> nodeSets;  // set name -> node id list file
  std::map<std::int64_t, Eigen::Vector3d> externalPoints;
};

struct AnsysModel {
  ImportedMesh imported;
  AnsysComponents components;
  std::vector<MuscleFibres> fibres;
};

AnsysModel readAnsysModel(const AnsysModelFiles &files);

}  // namespace glossa::mesh
