#pragma once
// Adds element matrices into a compressed-row matrix by offsets found once, not searched per
// entry. Tpetra's sumIntoGlobalValues maps the row and each of the 24 columns from global to local
// indices and searches the row for each: most of an assembly's cost on small meshes, several
// times the element kernel itself. The pattern never changes during a run (the graph is built
// once), so the position of every element entry in the values array is fixed and found here.
//
// Trilinos-free: it sees the local pattern as plain arrays (row pointers and column indices) and
// the element's local row and column indices; the Assembler hands it Tpetra's views.
//
// Storage: where a node's three dofs sit side by side in every row (true for the layouts
// Glossa builds: dofs 3n, 3n+1, 3n+2 of a node stay consecutive in the column map), one offset per
// element row and node (192 per element), else one per entry (576).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fem/Q1P0Element.hpp"

namespace glossa::assembly {

class ElementScatter {
public:
  using Indices = std::array<int, 24>;

  // rowPointers has numRows + 1 entries, columns the column index of every stored entry (sorted
  // or not within a row); rows[e] and columns[e] are element e's local row and column indices.
  // Throws std::logic_error naming the element if an entry is not in the pattern.
  ElementScatter(const std::size_t *rowPointers, const int *columns, std::size_t numRows,
                 const std::vector<Indices> &rows, const std::vector<Indices> &columnIndices);

  // values[offset] += ke for element e.
  void add(std::size_t e, const fem::ElementMatrix &ke, double *values) const;

  // Offsets stored per element: 192 (a node's three columns side by side) or 576.
  int offsetsPerElement() const { return perElement_; }
  std::size_t elements() const { return perElement_ ? offsets_.size() / static_cast<std::size_t>(perElement_) : 0; }

private:
  bool build(const std::size_t *rowPointers, const int *columns, std::size_t numRows, const std::vector<Indices> &rows,
             const std::vector<Indices> &columnIndices, bool byNode);
  int perElement_ = 0;
  std::vector<std::uint32_t> offsets_;
};

} // namespace glossa::assembly
