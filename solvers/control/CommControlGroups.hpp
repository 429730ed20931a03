#pragma once
// Control groups on a Teuchos communicator: the world's ranks split into `count` groups of
// consecutive ranks (Comm::split), each group with its own sub-communicator on which it builds
// and runs a whole copy of the solver (doc/control.md, "The control driver"). With several groups,
// a generation's candidates go to the groups as they finish (claim): a counter on rank 0, which
// each group's root increments by MPI's atomic fetch-and-add (one-sided, passive target).

#include <mpi.h>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "solvers/control/ControlGroups.hpp"

namespace glossa::solvers {

class CommControlGroups final : public ControlGroups {
public:
  // `count` >= 1 divides world->getSize() (the caller checks, to name its option). Collective.
  CommControlGroups(Teuchos::RCP<const Teuchos::Comm<int>> world, int count);
  ~CommControlGroups() override;
  CommControlGroups(const CommControlGroups &) = delete;
  CommControlGroups &operator=(const CommControlGroups &) = delete;

  // This rank's group's communicator (the world itself for one group).
  const Teuchos::RCP<const Teuchos::Comm<int>> &groupComm() const { return group_; }

  int count() const override { return count_; }
  int mine() const override { return mine_; }
  std::vector<double> sumOfGroupRoots(const std::vector<double> &values) const override;
  void broadcastFromGroup(int from, std::vector<double> &buffer) const override;
  long claim(std::size_t size) const override;

private:
  Teuchos::RCP<const Teuchos::Comm<int>> world_, group_;
  int count_, size_, mine_;
  MPI_Win counter_ = MPI_WIN_NULL; // several groups: the claims so far, on rank 0
  mutable long batchStart_ = 0;    // the counter's value when this batch began
  mutable long claimed_ = 0;       // one group: the counter, kept here
};

} // namespace glossa::solvers
