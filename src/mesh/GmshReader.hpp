#pragma once
// Reader for Gmsh's MSH 4.1 ASCII format (https://gmsh.info/doc/texinfo/gmsh.html, "MSH file
// format"), written from the specification: no libgmsh, so a user's mesh needs no Gmsh install.
// doc/meshes.md lists what is read and the errors.

#include <string>

#include "mesh/ImportedMesh.hpp"

namespace glossa::mesh {

// Reads $MeshFormat (must be 4.1, ASCII), $PhysicalNames, $Entities, $Nodes and $Elements;
// other sections are skipped up to their $End line.
// - Every 8-node hexahedron (type 5) becomes an element, in file order. Gmsh's hexahedron node
//   order is VTK's (nodes 0-3 one face counter-clockwise seen from the other, 4-7 above them),
//   so nodes are copied; a non-positive Jacobian at a Gauss point is refused as inverted.
// - A physical group of dimension 3 becomes an element set; of dimension 2 a face set (each
//   4-node quadrangle, type 3, matched to the hexahedron face with the same nodes) and the node
//   set of its nodes under the same name; of dimension 1 or 0 a node set (of its 2-node lines,
//   type 1, or points, type 15). Groups without a $PhysicalNames entry are named
//   "physical<dim>d_<tag>" (e.g. "physical3d_7").
// - Refused, with "file:line: reason": other versions or binary files, partitioned files, any
//   non-hexahedral element in a volume entity and any element that cannot be mapped in a
//   grouped surface, curve or point entity (naming the Gmsh type), references to unknown nodes
//   or entities, duplicate node or element tags, counts that disagree with their headers,
//   malformed numbers, missing $EndXxx lines, a quadrangle that is no hexahedron face.
ImportedMesh readGmsh(const std::string &file);

}  // namespace glossa::mesh
