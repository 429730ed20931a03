#pragma once
// The exchanges among control groups (--control-groups, doc/control.md) that the control driver
// makes: the ranks split into groups, each solving some of a generation's candidates on its own
// sub-communicator. Every rank must then see the same objectives, and the winning group's state
// must reach every group.
// Abstract so that the driver tests without MPI; CommControlGroups is the Teuchos one.

#include <cstddef>
#include <vector>

namespace glossa::solvers {

class ControlGroups {
public:
  virtual ~ControlGroups() = default;

  virtual int count() const = 0;
  virtual int mine() const = 0; // this rank's group, in [0, count())

  // The element-wise sum over the world of every group root's `values` (the other ranks'
  // count as 0), on every rank: each group root holds the entries its group computed, 0 elsewhere.
  virtual std::vector<double> sumOfGroupRoots(const std::vector<double> &values) const = 0;
  // The buffer of group `from`'s root, size included, on every rank.
  virtual void broadcastFromGroup(int from, std::vector<double> &buffer) const = 0;
  // A batch of `size` candidates shared out as they finish: the index of the next candidate for
  // this rank's group to solve, or -1 once every candidate of the batch is taken. Every group
  // claims each batch to its end (-1), the batches in the same order; the -1 is collective over
  // the world, the others over this rank's group (its ranks get the same indices).
  virtual long claim(std::size_t size) const = 0;
};

// One group: every rank solves every candidate, and nothing is exchanged.
class SingleControlGroup final : public ControlGroups {
public:
  int count() const override { return 1; }
  int mine() const override { return 0; }
  std::vector<double> sumOfGroupRoots(const std::vector<double> &values) const override { return values; }
  void broadcastFromGroup(int, std::vector<double> &) const override {}
  long claim(std::size_t size) const override {
    if (next_ < size) return static_cast<long>(next_++);
    next_ = 0;
    return -1;
  }

private:
  mutable std::size_t next_ = 0;
};

} // namespace glossa::solvers
