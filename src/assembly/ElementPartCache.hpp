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
// lambda_c, and where the local solves start). A passive element's part depends on the
// displacement alone, so a hit returns the bits a fresh evaluation would.
//
// Memory: about 11 KB per local element (two 24x24 matrices), allocated on first use.

#include <cstdint>
#include <vector>

#include "fem/Q1P0Element.hpp"
#include "materials/MuscleMaterial.hpp"
#include "model/TissuePointLaw.hpp"

namespace glossa::assembly {

// Whether an assembler's element passes keep each element's part for the next pass at the same
// state (Kept, the default) or evaluate every pass afresh (bench/assembly_cost measures the
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
  fem::Q1P0DisplacementPart part;
  model::ElementMuscleResponse muscle; // a muscle element's point-law record
};

class ElementPartCache {
public:
  explicit ElementPartCache(std::size_t elements) : elements_(elements) {}

  // Local element i's part if it was evaluated at `key` with at least `what`; null otherwise.
  const ElementPart *find(std::size_t i, const ElementPartKey &key, fem::Q1P0Output what) const {
    if (entries_.empty() || !filled_[i] || !(entries_[i].key == key)) return nullptr;
    const ElementPart &entry = entries_[i];
    if (what == fem::Q1P0Output::ResidualAndTangent && !entry.part.withTangent) return nullptr;
    return &entry;
  }
  // The slot of local element i, to be filled for `key` (its previous part is dropped); it is
  // found only once kept(i) says the evaluation finished, so a law that throws leaves nothing.
  ElementPart &slot(std::size_t i, const ElementPartKey &key) {
    if (entries_.empty()) {
      entries_.resize(elements_);
      filled_.assign(elements_, 0);
    }
    filled_[i] = 0;
    entries_[i].key = key;
    entries_[i].muscle = model::ElementMuscleResponse{};
    return entries_[i];
  }
  void kept(std::size_t i) { filled_[i] = 1; }
  void count(bool hit) const { ++(hit ? hits_ : misses_); }
  ElementPartCounts counts() const { return {hits_, misses_}; }

private:
  std::size_t elements_;
  std::vector<ElementPart> entries_;
  std::vector<char> filled_;
  mutable std::uint64_t hits_ = 0, misses_ = 0;
};

} // namespace glossa::assembly
