#include "assembly/ElementScatter.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace glossa::assembly {

namespace {
// Position of `column` in row `row` of the pattern, or npos.
constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();
std::size_t find(const std::size_t *rowPointers, const int *columns, int row, int column) {
  for (std::size_t k = rowPointers[row]; k < rowPointers[row + 1]; ++k)
    if (columns[k] == column) return k;
  return npos;
}
} // namespace

ElementScatter::ElementScatter(const std::size_t *rowPointers, const int *columns, std::size_t numRows,
                               const std::vector<Indices> &rows, const std::vector<Indices> &columnIndices) {
  if (rows.size() != columnIndices.size()) throw std::logic_error("ElementScatter: rows and columns differ in length");
  if (numRows > 0 && rowPointers[numRows] > std::numeric_limits<std::uint32_t>::max())
    throw std::logic_error("ElementScatter: more than 2^32 stored entries on one rank");
  if (!build(rowPointers, columns, numRows, rows, columnIndices, /*byNode=*/true))
    build(rowPointers, columns, numRows, rows, columnIndices, /*byNode=*/false);
}

bool ElementScatter::build(const std::size_t *rowPointers, const int *columns, std::size_t numRows,
                           const std::vector<Indices> &rows, const std::vector<Indices> &columnIndices, bool byNode) {
  perElement_ = byNode ? 24 * 8 : 24 * 24;
  offsets_.assign(rows.size() * static_cast<std::size_t>(perElement_), 0);
  for (std::size_t e = 0; e < rows.size(); ++e) {
    std::uint32_t *out = &offsets_[e * static_cast<std::size_t>(perElement_)];
    for (int l = 0; l < 24; ++l) {
      const int row = rows[e][l];
      if (row < 0 || static_cast<std::size_t>(row) >= numRows)
        throw std::logic_error("ElementScatter: element " + std::to_string(e) + " has a row outside the pattern");
      for (int m = 0; m < 24; ++m) {
        if (byNode && m % 3 != 0) continue;
        const std::size_t k = find(rowPointers, columns, row, columnIndices[e][m]);
        if (k == npos)
          throw std::logic_error("ElementScatter: entry (" + std::to_string(l) + ", " + std::to_string(m) +
                                 ") of element " + std::to_string(e) + " is not in the pattern");
        if (byNode) {
          // The node's other two columns must follow in the same row.
          for (int c = 1; c < 3; ++c)
            if (k + static_cast<std::size_t>(c) >= rowPointers[row + 1] ||
                columns[k + static_cast<std::size_t>(c)] != columnIndices[e][m + c])
              return false;
          out[l * 8 + m / 3] = static_cast<std::uint32_t>(k);
        } else {
          out[l * 24 + m] = static_cast<std::uint32_t>(k);
        }
      }
    }
  }
  return true;
}

void ElementScatter::add(std::size_t e, const fem::ElementMatrix &ke, double *values) const {
  const std::uint32_t *offset = &offsets_[e * static_cast<std::size_t>(perElement_)];
  if (perElement_ == 24 * 8) {
    for (int l = 0; l < 24; ++l)
      for (int b = 0; b < 8; ++b) {
        double *v = values + offset[l * 8 + b];
        v[0] += ke(l, 3 * b);
        v[1] += ke(l, 3 * b + 1);
        v[2] += ke(l, 3 * b + 2);
      }
  } else {
    for (int l = 0; l < 24; ++l)
      for (int m = 0; m < 24; ++m) values[offset[l * 24 + m]] += ke(l, m);
  }
}

} // namespace glossa::assembly
