#pragma once
// Writers of a HexMesh with its sets, for `glossa mesh FILE --output OUT.msh|OUT.inp`: a mesh
// imported from one format (or refined) goes back to a mesher or another solver, and Glossa's
// own readers read it back to the same mesh (tests/unit/mesh/test_mesh_writer.cpp).
// Node n is written with id n + 1 and element e with id e + 1, nodes and elements in the mesh's
// order, so that the file read back numbers them as before. Named points and fibre polylines
// are not written (neither format has them).

#include <string>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// MSH 4.1 ASCII, as Gmsh reads it:
// - element sets: physical volumes (dim 3); an element's volume entity stands for its
//   combination of sets (Gmsh keeps one entity per element), consecutive elements of one
//   entity share an element block so the file order is the mesh's;
// - face sets: physical surfaces (dim 2) of 4-node quadrangles, each face's nodes in
//   kHexFaceNodes order (its normal points out of the element), one surface entity per
//   combination of face sets;
// - node sets: a face set's node set of the same name is implied by the surface group and not
//   written again; every other node set is a physical point group (dim 0) of 1-node points,
//   each on a point entity of its own (Gmsh classifies a node on one entity).
// Throws MeshError naming the set when a node set has a face set's name but other nodes (the
// file cannot tell them apart) or a name holds a '"'; std::runtime_error (not a MeshError) when
// the file cannot be written.
void writeGmsh(const HexMesh &mesh, const std::string &file);

// Abaqus .inp: *NODE, *ELEMENT TYPE=C3D8, an *ELSET per element set, an *NSET per node set and
// a *SURFACE (TYPE=ELEMENT) per face set with "element, Sk" lines, Sk = local face k-1 (the
// numbering AbaqusReader.hpp documents). Throws MeshError for a set name with ',' or '=' (a
// keyword line could not hold it); std::runtime_error when the file cannot be written.
void writeAbaqus(const HexMesh &mesh, const std::string &file);

}  // namespace glossa::mesh
