#pragma once
// Each local element's last displacement part (fem::Q1P0DisplacementPart: the point laws and the
// element matrices before any pressure), with what it was evaluated from. An element pass at the
// same displacement and point-law inputs finishes from it instead of evaluating again:
// - the first Newton pass after an Uzawa update, whose multipliers change only the pressure;
// - a Newton solve's passes that repeat its last state (a converged check, then the tangent);
// - the muscle history's and the output's passes at the converged state (for a muscle element the
//   part keeps what its point laws computed: lambda_c, the fibre stretch and tension).
// The part is a function of the displacement and of the point law's inputs, which the key holds:
// the element's nodal displacements, and for a muscle element its families' trial activation,
// the step size and the history's revision (model::MuscleHistory::revision: the committed
// lambda_c, and where the local solves start).
//
// Only muscle elements keep their parts: their point laws (the Hill muscle's local solves) are
// the cost worth 11 KB an element (two 24x24 matrices, allocated on first use). A passive
// element's law is cheap beside the memory traffic of keeping it: on the step-44 block at 32^3
// keeping every element cost 340 MB and saved 5 % of the assembly (doc/performance.md), so a
// passive scene keeps nothing and pays nothing.

#include <cstdint>
#include <vector>

#include "fem/Q1P0Element.hpp"
#include "materials/MuscleMaterial.hpp"
#include "model/TissuePointLaw.hpp"

namespace glossa::assembly {

// Whether an assembler's element passes keep each muscle element's part for the next pass at the
// same state (Kept, the default) or evaluate every pass afresh (bench/assembly_cost measures the
// element work that way).
enum class ElementParts { Kept, Fresh };

// Element evaluations finished from a kept part, and evaluated, since the start.
struct ElementPartCounts {
  std::uint64_t reused = 0, evaluated = 0;
};

struct ElementPartKey {
  fem::NodeMatrix u = fem::NodeMatrix::Zero();
  materials::FamilyValues alpha; // empty for a passive element
  double dt = 0.0;
  std::uint64_t revision = 0;

  bool operator==(const ElementPartKey &other) const {
    return u == other.u && alpha.size() == other.alpha.size() && alpha == other.alpha && dt == other.dt &&
           revision == other.revision;
  }
};

struct ElementPart {
  ElementPartKey key;
  bool filled = false; // the evaluation at `key` finished
  fem::Q1P0DisplacementPart part;
  model::ElementMuscleResponse muscle; // a muscle element's point-law record
};

class ElementPartCache {
public:
  // `keeps[i]`: whether local element i keeps its part.
  explicit ElementPartCache(const std::vector<char> &keeps) : slotOf_(keeps.size(), -1) {
    for (std::size_t i = 0; i < keeps.size(); ++i)
      if (keeps[i]) slotOf_[i] = slots_++;
  }

  bool keeps(std::size_t i) const { return slotOf_[i] >= 0; }
  // Local element i's part if it was evaluated at `key` with at least `what`; null otherwise.
  const ElementPart *find(std::size_t i, const ElementPartKey &key, fem::Q1P0Output what) const {
    if (entries_.empty() || !keeps(i)) return nullptr;
    const ElementPart &entry = entries_[static_cast<std::size_t>(slotOf_[i])];
    if (!entry.filled || !(entry.key == key)) return nullptr;
    if (what == fem::Q1P0Output::ResidualAndTangent && !entry.part.withTangent) return nullptr;
    return &entry;
  }
  // The slot of local element i (one that keeps), to be filled for `key` (its previous part is
  // dropped); it is found only once kept(i) says the evaluation finished, so a law that throws
  // leaves nothing.
  ElementPart &slot(std::size_t i, const ElementPartKey &key) {
    if (entries_.empty()) entries_.resize(static_cast<std::size_t>(slots_));
    ElementPart &entry = entries_[static_cast<std::size_t>(slotOf_[i])];
    entry.filled = false;
    entry.key = key;
    entry.muscle = model::ElementMuscleResponse{};
    return entry;
  }
  void kept(std::size_t i) { entries_[static_cast<std::size_t>(slotOf_[i])].filled = true; }
  void count(bool hit) const { ++(hit ? hits_ : misses_); }
  ElementPartCounts counts() const { return {hits_, misses_}; }

private:
  std::vector<int> slotOf_; // -1: the element keeps no part
  int slots_ = 0;
  std::vector<ElementPart> entries_;
  mutable std::uint64_t hits_ = 0, misses_ = 0;
};

} // namespace glossa::assembly
