#pragma once
// Reader for the mesh part of Abaqus input files (.inp), flat (one part, no instance
// transformations), as Gmsh, meshio and most meshers write them. doc/meshes.md lists what is
// read, the face numbering and the errors.

#include <string>

#include "mesh/ImportedMesh.hpp"

namespace glossa::mesh {

// Keywords (case-insensitive, "**" comments, keyword lines continued by a trailing comma):
// - *NODE[, NSET=n]: "id, x, y, z".
// - *ELEMENT, TYPE=t[, ELSET=n]: C3D8, C3D8H, C3D8R and C3D8RH are hexahedra (Abaqus's node
//   order is VTK's; the formulation suffix is irrelevant, Glossa's Q1-P0 element replaces it);
//   4-node quadrilaterals (CPS4, CPS4R, CPE4, CPE4R, S4, S4R, R3D4, M3D4, M3D4R, SFM3D4,
//   SFM3D4R) are read only as sources of face sets, 2-node lines (T3D2, T2D2, B31, B21) only as
//   sources of node sets; any other type is refused, naming it.
//   Data lines may continue over several lines.
// - *ELSET, ELSET=n[, GENERATE] and *NSET, NSET=n[, GENERATE]: ids (or names of sets defined
//   before), or "first, last[, step]" with GENERATE.
// - *SURFACE[, TYPE=ELEMENT], NAME=n: "element-or-elset, Sk" lines; face Sk of a C3D8 is
//   Glossa's local face k-1 (S1 bottom 1-2-3-4, S2 top 5-8-7-6, S3 1-5-6-2, S4 2-6-7-3,
//   S5 3-7-8-4, S6 4-8-5-1; identical to kHexFaceNodes' order).
// An ELSET of hexahedra becomes an element set; an ELSET of quadrilaterals becomes a face set
// (each matched to the hexahedron face with its nodes); an ELSET of lines becomes the node set
// of their nodes (Gmsh's export of a physical curve); a *SURFACE becomes a face set; each
// face set also gives the node set of its nodes under the same name unless an NSET has that
// name. Other keywords (*HEADING, *MATERIAL, *STEP, ...) and their data are skipped; *INCLUDE,
// a second *PART and positioned *INSTANCEs are refused. Errors: std::runtime_error
// "file:line: reason".
ImportedMesh readAbaqus(const std::string &file);

}  // namespace glossa::mesh
