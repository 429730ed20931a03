#pragma once
// Reader for Gmsh's MSH format (https://gmsh.info/doc/texinfo/gmsh.html, "MSH file format"),
// versions 4.1 and 2.2, ASCII and binary, as `gmsh -format msh41|msh22 [-bin]` writes them;
// written from the specification: no libgmsh, so a user's mesh needs no Gmsh install.
// doc/meshes.md lists what is read and the errors. The parsers (GmshAsciiParser.cpp,
// GmshBinaryParser.cpp) read the encodings; GmshAssembly.hpp holds the rules they share.

#include <string>

#include "mesh/ImportedMesh.hpp"

namespace glossa::mesh {

// Reads $MeshFormat (4.1 or 2.2; file-type 0 ASCII or 1 binary, data-size 8, the binary
// endianness marker 1), $PhysicalNames, $Entities (4.1), $Nodes and $Elements; other sections
// are skipped up to their $End line.
// - Every hexahedron becomes an element, in file order: 8-node (type 5) as it is, 20-node
//   (type 17) and 27-node (type 12) by their 8 corners (Gmsh lists them first, in the 8-node
//   order), which makes the geometry trilinear; the nodes only such elements used (edge, face,
//   centre nodes) are dropped and the others renumbered in file order, so that the mesh checks
//   before a run do not refuse them as unused, and ImportedMesh::notes says so once. Gmsh's
//   hexahedron node order is VTK's, so nodes are copied; a non-positive Jacobian at a Gauss
//   point is refused as inverted.
// - A physical group of dimension 3 becomes an element set; of dimension 2 a face set (each
//   quadrangle, type 3, or by its corners type 16 or 10, matched to the hexahedron face with the
//   same corners) and the node set of its corners under the same name; of dimension 1 or 0 a
//   node set (of its lines' ends, types 1 and 8, or points, type 15). Groups without a
//   $PhysicalNames entry are named "physical<dim>d_<tag>" (e.g. "physical3d_7"). MSH 2 writes
//   an element of k groups as k elements with new tags: a hexahedron repeated in the same
//   entity with other groups is one element in all of them (the first tag is its id).
// - Refused, with "file:line: reason" (ASCII) or "file: byte N: reason" (binary): other
//   versions, other data sizes, a big-endian or broken endianness marker; partitioned files;
//   tetrahedra, prisms and pyramids (by name, with the Gmsh setting that gives hexahedra
//   instead) and any other non-hexahedral element in a volume; triangles or other elements in a
//   grouped surface, curve or point entity; references to unknown nodes or entities, duplicate
//   node or element tags, counts that disagree with their headers or with the bytes left,
//   malformed numbers, missing $EndXxx lines, a quadrangle that is no hexahedron face.
ImportedMesh readGmsh(const std::string &file);

}  // namespace glossa::mesh
