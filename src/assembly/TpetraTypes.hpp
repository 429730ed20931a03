#pragma once
// The Tpetra instantiation Debian 12's Trilinos 13.2 provides: double, int, long long, Serial.

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace glossa::assembly {

using Map = Tpetra::Map<>;
using LO = Map::local_ordinal_type;
using GO = Map::global_ordinal_type;
using Node = Map::node_type;
using Vector = Tpetra::Vector<double, LO, GO, Node>;
using MultiVector = Tpetra::MultiVector<double, LO, GO, Node>;
using CrsMatrix = Tpetra::CrsMatrix<double, LO, GO, Node>;
using FEGraph = Tpetra::FECrsGraph<LO, GO, Node>;
using FEMatrix = Tpetra::FECrsMatrix<double, LO, GO, Node>;
using Import = Tpetra::Import<LO, GO, Node>;
using Export = Tpetra::Export<LO, GO, Node>;
using Comm = Teuchos::Comm<int>;

} // namespace glossa::assembly
