// ElementScatter against a dense sum of the same element matrices: the offsets it finds once must
// put every entry where a search would.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <stdexcept>

#include "assembly/ElementScatter.hpp"

namespace glossa::assembly {
namespace {

struct Pattern {
  std::vector<std::size_t> rowPointers;
  std::vector<int> columns;
};

// The compressed-row pattern of the union of the elements' 24 x 24 blocks, columns sorted in each
// row (or reversed, to break the "node's three columns side by side" layout).
Pattern patternOf(const std::vector<ElementScatter::Indices> &dofs, int n, bool reversed) {
  std::vector<std::set<int>> rows(static_cast<std::size_t>(n));
  for (const auto &e : dofs)
    for (int r : e) rows[static_cast<std::size_t>(r)].insert(e.begin(), e.end());
  Pattern p;
  p.rowPointers.push_back(0);
  for (const auto &r : rows) {
    std::vector<int> c(r.begin(), r.end());
    if (reversed) std::reverse(c.begin(), c.end());
    p.columns.insert(p.columns.end(), c.begin(), c.end());
    p.rowPointers.push_back(p.columns.size());
  }
  return p;
}

// Two hexahedra sharing a face (12 nodes, 36 dofs), node order scrambled in the second.
std::vector<ElementScatter::Indices> twoElements() {
  const std::array<int, 8> a{0, 1, 2, 3, 4, 5, 6, 7}, b{5, 8, 9, 6, 1, 10, 11, 2};
  std::vector<ElementScatter::Indices> dofs(2);
  for (int k = 0; k < 8; ++k)
    for (int c = 0; c < 3; ++c) {
      dofs[0][3 * k + c] = 3 * a[k] + c;
      dofs[1][3 * k + c] = 3 * b[k] + c;
    }
  return dofs;
}

void expectScatterMatchesDenseSum(bool reversed, int expectedOffsets) {
  const auto dofs = twoElements();
  const int n = 36;
  const Pattern p = patternOf(dofs, n, reversed);
  const ElementScatter scatter(p.rowPointers.data(), p.columns.data(), n, dofs, dofs);
  EXPECT_EQ(scatter.offsetsPerElement(), expectedOffsets);
  EXPECT_EQ(scatter.elements(), 2u);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> values(p.columns.size(), 0.0);
  std::vector<double> dense(static_cast<std::size_t>(n * n), 0.0);
  for (std::size_t e = 0; e < dofs.size(); ++e) {
    fem::ElementMatrix ke;
    for (int l = 0; l < 24; ++l)
      for (int m = 0; m < 24; ++m) ke(l, m) = d(rng);
    scatter.add(e, ke, values.data());
    for (int l = 0; l < 24; ++l)
      for (int m = 0; m < 24; ++m) dense[static_cast<std::size_t>(dofs[e][l] * n + dofs[e][m])] += ke(l, m);
  }
  for (int r = 0; r < n; ++r)
    for (std::size_t k = p.rowPointers[static_cast<std::size_t>(r)]; k < p.rowPointers[static_cast<std::size_t>(r) + 1]; ++k)
      EXPECT_EQ(values[k], dense[static_cast<std::size_t>(r * n + p.columns[k])]) << "row " << r << " column " << p.columns[k];
}

TEST(ElementScatter, NodeByNodeOffsetsGiveTheDenseSum) { expectScatterMatchesDenseSum(false, 192); }

TEST(ElementScatter, EntryByEntryOffsetsWhenANodesColumnsAreNotSideBySide) { expectScatterMatchesDenseSum(true, 576); }

TEST(ElementScatter, AnEntryOutsideThePatternIsRefused) {
  auto dofs = twoElements();
  const Pattern p = patternOf(dofs, 36, false);
  dofs[1][0] = 0; // node 5's x dof replaced by node 0's, which element 1 does not couple to node 8
  EXPECT_THROW(ElementScatter(p.rowPointers.data(), p.columns.data(), 36, dofs, dofs), std::logic_error);
}

} // namespace
} // namespace glossa::assembly
