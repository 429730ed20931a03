#include "solvers/linear/MumpsPreconditioner.hpp"
#include "solvers/linear/DirectFactorStatistics.hpp"

#include "assembly/TimeSplit.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <dmumps_c.h>
#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

namespace glossa::solvers {

namespace {
std::atomic<int> newtonSolveEpoch{0}, stepEpoch{0};

MPI_Comm rawComm(const Teuchos::Comm<int> &comm) {
  const auto *mpi = dynamic_cast<const Teuchos::MpiComm<int> *>(&comm);
  if (!mpi) throw std::logic_error("MUMPS needs an MPI communicator");
  return *mpi->getRawMpiComm();
}

// MUMPS's ICNTL(7) for an ordering's name and the unknowns. With neither METIS nor SCOTCH in
// Debian's build, MUMPS's own choice (7) takes AMF for the small tangents solved directly, which
// costs 1.6x the flops of PORD (MUMPS's built-in nested dissection) on the coarse tongue and 1.7x
// on the section 7.1 block (doc/performance.md, "The direct solver's ordering"). PORD ends the
// process on a graph too small to dissect (a single element: "no valid number of stages in
// multisector"), so auto takes it only from kPordFrom unknowns, where it also begins to pay.
constexpr long long kPordFrom = 1000;
int orderingControl(const std::string &name, long long unknowns) {
  if (name == "AMD") return 0;
  if (name == "AMF") return 2;
  if (name == "QAMD") return 6;
  if (name == "PORD") return 4;
  return unknowns >= kPordFrom ? 4 : 7; // auto
}

std::string orderingName(int infog7) {
  switch (infog7) {
  case 0: return "AMD";
  case 2: return "AMF";
  case 3: return "SCOTCH";
  case 4: return "PORD";
  case 5: return "METIS";
  case 6: return "QAMD";
  default: return "other (" + std::to_string(infog7) + ")";
  }
}

DirectFactorStatistics lastStatistics;
} // namespace

const DirectFactorStatistics &lastDirectFactorisation() { return lastStatistics; }

// One MUMPS instance: the pattern of the matrix it analysed, and its current numerical factors.
// Gathered (on several ranks): MUMPS runs on rank 0 alone, on a communicator of that rank, and the
// other ranks send it their rows' entries. A factorisation shared out among ranks schedules its
// work dynamically, so the last bits of its answer vary from run to run; on one rank they do not.
class MumpsFactorization {
public:
  // `ordering`: the name orderingControl turns into MUMPS's ICNTL(7) at each analysis.
  MumpsFactorization(const Teuchos::RCP<const Teuchos::Comm<int>> &comm, bool symmetric, bool gathered,
                     std::string ordering)
      : comm_(comm), symmetric_(symmetric), gathered_(gathered && comm->getSize() > 1), ordering_(std::move(ordering)) {
    MPI_Comm mumpsComm = rawComm(*comm);
    if (gathered_) {
      MPI_Comm_split(mumpsComm, comm->getRank() == 0 ? 0 : MPI_UNDEFINED, 0, &rootComm_);
      mumpsComm = rootComm_;
    }
    inMumps_ = mumpsComm != MPI_COMM_NULL;
    id_.comm_fortran = inMumps_ ? static_cast<MUMPS_INT>(MPI_Comm_c2f(mumpsComm)) : 0;
    id_.par = 1;                    // the host takes part in the factorisation
    id_.sym = symmetric ? 2 : 0;    // 2: symmetric, possibly indefinite (LDL^T with 2x2 pivots)
    call(-1);
    check("initialisation");
    for (int k : {1, 2, 3}) id_.icntl[k - 1] = -1; // no MUMPS output
    id_.icntl[3] = 0;
    id_.icntl[17] = 3;  // ICNTL(18): entries given distributed, each rank its owned rows
    id_.icntl[13] = 40; // ICNTL(14): working-space margin, % (pivoting of indefinite tangents needs room)
  }
  ~MumpsFactorization() {
    // Ending the instance is collective (MUMPS frees the communicator it duplicated). While an
    // exception unwinds on one rank the others are elsewhere, and it deadlocked: a deleted output
    // directory on 2 ranks left both waiting until killed. The job is ending then: leave it.
    // Gathered, the instance lives on rank 0 alone and ends there without the others.
    if (!gathered_ && std::uncaught_exceptions() > 0) return;
    if (inMumps_) {
      id_.job = -2;
      dmumps_c(&id_);
    }
    if (rootComm_ != MPI_COMM_NULL) MPI_Comm_free(&rootComm_);
  }
  MumpsFactorization(const MumpsFactorization &) = delete;
  MumpsFactorization &operator=(const MumpsFactorization &) = delete;

  // Numerical factorisation of A, after an analysis if A's pattern is not the analysed one. The
  // pattern is read once per local graph (the Assembler's graph serves the whole run); every
  // later factorisation only gathers the values.
  void factor(const assembly::CrsMatrix &A) {
    const auto local = A.getLocalMatrixHost();
    const long long n = static_cast<long long>(A.getGlobalNumRows());
    const void *pattern = local.graph.entries.data();
    int changed = pattern != pattern_ || n != n_ || static_cast<std::size_t>(local.nnz()) != patternEntries_ ? 1 : 0, anyChanged = 0;
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, changed, Teuchos::outArg(anyChanged));
    if (anyChanged) {
      readPattern(A, n);
      pattern_ = pattern;
      patternEntries_ = static_cast<std::size_t>(local.nnz());
      n_ = n;
      if (gathered_) gatherPattern();
      id_.n = static_cast<MUMPS_INT>(n);
      id_.nnz_loc = static_cast<MUMPS_INT8>(mumpsRows().size());
      id_.irn_loc = mumpsRows().data();
      id_.jcn_loc = mumpsCols().data();
      id_.a_loc = mumpsValues().data();
      id_.icntl[6] = orderingControl(ordering_, n); // ICNTL(7): the fill-reducing ordering
      const assembly::PartTimer timer(assembly::TimedPart::analysis);
      call(1);
      check("analysis");
    }
    for (std::size_t k = 0; k < take_.size(); ++k) values_[k] = local.values(take_[k]);
    if (gathered_) gatherValues();
    id_.a_loc = mumpsValues().data();
    const assembly::PartTimer timer(assembly::TimedPart::factorisation);
    for (int attempt = 0;; ++attempt) {
      call(2);
      // -8, -9: the working space estimated by the analysis was too small (pivoting): more room.
      if ((id_.infog[0] == -8 || id_.infog[0] == -9) && attempt < 3) {
        id_.icntl[13] *= 2;
        continue;
      }
      break;
    }
    check("factorisation");
    if (inMumps_) {
      // INFOG(29) counts in millions, negated, once it would overflow an int.
      const double entries = id_.infog[28] >= 0 ? id_.infog[28] : -1e6 * id_.infog[28];
      lastStatistics = {orderingName(id_.infog[6]), entries, id_.rinfog[2]};
    }
    factoredMatrix_ = &A;
    factoredEpoch_ = newtonSolveEpoch;
    factoredStep_ = stepEpoch;
    negativePivots_ = symmetric_ ? id_.infog[11] : 0; // INFOG(12): negative pivots of LDL^T
    appliesAtInit_ = applies_;
  }

  // With reuse k > 0: the factors of an earlier tangent of this Newton solve (of this step, of the
  // run: `scope`) still serve A when the last solve with them took at most k Krylov iterations (one
  // preconditioner application each) and they had no negative pivot. An indefinite stale factor is
  // no preconditioner for CG: at full activation CG met negative curvature through one and every
  // step was cut back.
  bool stillServes(const assembly::CrsMatrix &A, int k, const std::string &scope) {
    const long long lastSolve = applies_ - appliesAtInit_;
    appliesAtInit_ = applies_;
    const bool sameScope = scope == "run"    ? true
                           : scope == "step" ? factoredStep_ == stepEpoch
                                             : factoredEpoch_ == newtonSolveEpoch;
    return k > 0 && factoredMatrix_ == &A && sameScope && lastSolve <= k && negativePivots_ == 0 &&
           static_cast<long long>(A.getGlobalNumRows()) == n_;
  }

  // x = A^-1 b (or A^-T b), the columns of b and x in the distribution of `map`.
  void solve(const assembly::MultiVector &b, assembly::MultiVector &x, bool transpose) {
    const assembly::PartTimer timer(assembly::TimedPart::directSolve);
    const auto map = b.getMap();
    if (rootMap_.is_null() || !rootMap_->isSameAs(*rootMapFor(map))) {
      rootMap_ = rootMapFor(map);
      toRoot_ = Teuchos::rcp(new assembly::Import(map, rootMap_));
      fromRoot_ = Teuchos::rcp(new assembly::Import(rootMap_, map));
    }
    const std::size_t nrhs = b.getNumVectors();
    assembly::MultiVector onRoot(rootMap_, nrhs);
    onRoot.doImport(b, *toRoot_, Tpetra::INSERT);
    std::vector<double> rhs;
    if (comm_->getRank() == 0) {
      rhs.resize(static_cast<std::size_t>(n_) * nrhs);
      for (std::size_t j = 0; j < nrhs; ++j) {
        const auto col = onRoot.getData(j);
        std::copy(col.begin(), col.end(), rhs.begin() + static_cast<std::ptrdiff_t>(j * n_));
      }
      id_.rhs = rhs.data();
      id_.nrhs = static_cast<MUMPS_INT>(nrhs);
      id_.lrhs = static_cast<MUMPS_INT>(n_);
    }
    ++applies_;
    id_.icntl[8] = transpose ? 0 : 1; // ICNTL(9): 1 solves A x = b, otherwise A^T x = b
    call(3);
    check("solve");
    if (comm_->getRank() == 0)
      for (std::size_t j = 0; j < nrhs; ++j) {
        auto col = onRoot.getDataNonConst(j);
        std::copy(rhs.begin() + static_cast<std::ptrdiff_t>(j * n_),
                  rhs.begin() + static_cast<std::ptrdiff_t>((j + 1) * n_), col.begin());
      }
    x.doImport(onRoot, *fromRoot_, Tpetra::INSERT);
  }

private:
  // MUMPS's 1-based coordinates of A's entries (with a symmetric matrix its upper triangle, the
  // half MUMPS reads) and where each value sits in A's local values.
  void readPattern(const assembly::CrsMatrix &A, long long n) {
    const auto local = A.getLocalMatrixHost();
    const auto rowMap = A.getRowMap();
    const auto colMap = A.getColMap();
    if (rowMap->getMinAllGlobalIndex() != 0 || rowMap->getMaxAllGlobalIndex() != n - 1)
      throw std::logic_error("MUMPS: the row map is not 0..N-1");
    rows_.clear();
    cols_.clear();
    take_.clear();
    const std::size_t localRows = local.numRows();
    for (std::size_t r = 0; r < localRows; ++r) {
      const auto gr = rowMap->getGlobalElement(static_cast<assembly::LO>(r));
      for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k) {
        const auto gc = colMap->getGlobalElement(local.graph.entries(k));
        if (symmetric_ && gc < gr) continue;
        rows_.push_back(static_cast<MUMPS_INT>(gr + 1));
        cols_.push_back(static_cast<MUMPS_INT>(gc + 1));
        take_.push_back(static_cast<std::size_t>(k));
      }
    }
    values_.resize(take_.size());
  }

  // A MUMPS job on the ranks that run MUMPS; gathered, rank 0 then tells the others what MUMPS
  // reported (INFOG(1), INFOG(2), INFOG(12): the status and the negative pivots), so that every
  // rank takes the same branch after it.
  void call(int job) {
    id_.job = job;
    if (inMumps_) dmumps_c(&id_);
    if (!gathered_) return;
    int info[3] = {id_.infog[0], id_.infog[1], id_.infog[11]};
    MPI_Bcast(info, 3, MPI_INT, 0, rawComm(*comm_));
    id_.infog[0] = info[0];
    id_.infog[1] = info[1];
    id_.infog[11] = info[2];
  }

  // Gathered: every rank's coordinates once per pattern, its values at every factorisation,
  // concatenated on rank 0 in rank order.
  void gatherPattern() {
    const int size = comm_->getSize();
    const int mine = static_cast<int>(take_.size());
    counts_.assign(static_cast<std::size_t>(size), 0);
    MPI_Gather(&mine, 1, MPI_INT, counts_.data(), 1, MPI_INT, 0, rawComm(*comm_));
    offsets_.assign(static_cast<std::size_t>(size), 0);
    for (int r = 1; r < size; ++r) offsets_[r] = offsets_[r - 1] + counts_[r - 1];
    const std::size_t all = comm_->getRank() == 0 ? static_cast<std::size_t>(offsets_.back() + counts_.back()) : 0;
    allRows_.resize(all);
    allCols_.resize(all);
    allValues_.resize(all);
    static_assert(sizeof(MUMPS_INT) == sizeof(int), "MUMPS_INT is sent as MPI_INT");
    MPI_Gatherv(rows_.data(), mine, MPI_INT, allRows_.data(), counts_.data(), offsets_.data(), MPI_INT, 0,
                rawComm(*comm_));
    MPI_Gatherv(cols_.data(), mine, MPI_INT, allCols_.data(), counts_.data(), offsets_.data(), MPI_INT, 0,
                rawComm(*comm_));
  }
  void gatherValues() {
    MPI_Gatherv(values_.data(), static_cast<int>(values_.size()), MPI_DOUBLE, allValues_.data(), counts_.data(),
                offsets_.data(), MPI_DOUBLE, 0, rawComm(*comm_));
  }
  std::vector<MUMPS_INT> &mumpsRows() { return gathered_ ? allRows_ : rows_; }
  std::vector<MUMPS_INT> &mumpsCols() { return gathered_ ? allCols_ : cols_; }
  std::vector<double> &mumpsValues() { return gathered_ ? allValues_ : values_; }

  Teuchos::RCP<const assembly::Map> rootMapFor(const Teuchos::RCP<const assembly::Map> &map) const {
    const auto n = map->getGlobalNumElements();
    return Teuchos::rcp(new assembly::Map(n, comm_->getRank() == 0 ? n : 0, 0, comm_));
  }
  void check(const char *what) const {
    if (id_.infog[0] >= 0) return;
    std::ostringstream m;
    m << "MUMPS " << what << " failed: INFOG(1) = " << id_.infog[0] << ", INFOG(2) = " << id_.infog[1];
    if (id_.infog[0] == -10) m << " (the tangent is numerically singular)";
    throw std::runtime_error(m.str());
  }

  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  bool symmetric_;
  bool gathered_;
  std::string ordering_;
  MPI_Comm rootComm_ = MPI_COMM_NULL; // gathered: rank 0 alone (MPI_COMM_NULL elsewhere)
  bool inMumps_ = true;               // this rank calls MUMPS
  std::vector<int> counts_, offsets_; // gathered: each rank's entries and where they start
  std::vector<MUMPS_INT> allRows_, allCols_;
  std::vector<double> allValues_;
  DMUMPS_STRUC_C id_{};
  long long n_ = -1;
  std::vector<MUMPS_INT> rows_, cols_;
  std::vector<std::size_t> take_;
  std::vector<double> values_;
  const void *pattern_ = nullptr;
  std::size_t patternEntries_ = 0;
  Teuchos::RCP<const assembly::Map> rootMap_;
  Teuchos::RCP<assembly::Import> toRoot_, fromRoot_;
  const assembly::CrsMatrix *factoredMatrix_ = nullptr;
  int factoredEpoch_ = -1, factoredStep_ = -1;
  int negativePivots_ = 0;
  long long applies_ = 0, appliesAtInit_ = 0;
};

namespace {
// The factorisation as a Tpetra operator: apply is the solve.
class MumpsInverse : public Tpetra::Operator<double, assembly::LO, assembly::GO, assembly::Node> {
public:
  MumpsInverse(std::shared_ptr<MumpsFactorization> f, Teuchos::RCP<const assembly::Map> domain,
               Teuchos::RCP<const assembly::Map> range)
      : f_(std::move(f)), domain_(std::move(domain)), range_(std::move(range)) {}
  Teuchos::RCP<const assembly::Map> getDomainMap() const override { return range_; }
  Teuchos::RCP<const assembly::Map> getRangeMap() const override { return domain_; }
  bool hasTransposeApply() const override { return true; }
  void apply(const assembly::MultiVector &X, assembly::MultiVector &Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    assembly::MultiVector Z(Y.getMap(), Y.getNumVectors());
    f_->solve(X, Z, mode != Teuchos::NO_TRANS);
    Y.update(alpha, Z, beta);
  }

private:
  std::shared_ptr<MumpsFactorization> f_;
  Teuchos::RCP<const assembly::Map> domain_, range_;
};
} // namespace

MumpsPreconditionerFactory::MumpsPreconditionerFactory() = default;
MumpsPreconditionerFactory::~MumpsPreconditionerFactory() = default;

void MumpsPreconditionerFactory::beginNewtonSolve() { ++newtonSolveEpoch; }

void MumpsPreconditionerFactory::beginStep() {
  ++newtonSolveEpoch;
  ++stepEpoch;
}

bool MumpsPreconditionerFactory::isCompatible(const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const {
  using ThyraOp = Thyra::TpetraLinearOp<double, assembly::LO, assembly::GO, assembly::Node>;
  const auto op = Teuchos::rcp_dynamic_cast<const ThyraOp>(fwdOpSrc.getOp());
  return !op.is_null() && !Teuchos::rcp_dynamic_cast<const assembly::CrsMatrix>(op->getConstTpetraOperator()).is_null();
}

Teuchos::RCP<Thyra::PreconditionerBase<double>> MumpsPreconditionerFactory::createPrec() const {
  return Teuchos::rcp(new Thyra::DefaultPreconditioner<double>);
}

void MumpsPreconditionerFactory::initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &fwdOpSrc,
                                                Thyra::PreconditionerBase<double> *prec,
                                                const Thyra::ESupportSolveUse) const {
  using ThyraOp = Thyra::TpetraLinearOp<double, assembly::LO, assembly::GO, assembly::Node>;
  const auto op = Teuchos::rcp_dynamic_cast<const ThyraOp>(fwdOpSrc->getOp(), true);
  const auto A = Teuchos::rcp_dynamic_cast<const assembly::CrsMatrix>(op->getConstTpetraOperator(), true);
  auto *defaultPrec = dynamic_cast<Thyra::DefaultPreconditioner<double> *>(prec);
  TEUCHOS_TEST_FOR_EXCEPTION(defaultPrec == nullptr, std::logic_error, "MUMPS: not a DefaultPreconditioner");
  const bool symmetric = params_.is_null() || params_->get<bool>("symmetric", true);
  const int reuse = params_.is_null() ? 0 : params_->get<int>("reuse iterations", 0);
  const std::string scope = params_.is_null() ? std::string("Newton solve") : params_->get<std::string>("reuse scope");
  const bool gathered = !params_.is_null() && params_->get<bool>("gathered", false);
  const std::string ordering = params_.is_null() ? std::string("auto") : params_->get<std::string>("ordering");
  if (!factorization_) factorization_ = std::make_shared<MumpsFactorization>(A->getComm(), symmetric, gathered, ordering);
  if (!factorization_->stillServes(*A, reuse, scope)) factorization_->factor(*A);
  auto inverse = Teuchos::rcp(new MumpsInverse(factorization_, A->getDomainMap(), A->getRangeMap()));
  const Teuchos::RCP<Thyra::LinearOpBase<double>> inverseOp =
      Thyra::tpetraLinearOp<double, assembly::LO, assembly::GO, assembly::Node>(
          Thyra::tpetraVectorSpace<double>(A->getDomainMap()), Thyra::tpetraVectorSpace<double>(A->getRangeMap()),
          Teuchos::RCP<Tpetra::Operator<double, assembly::LO, assembly::GO, assembly::Node>>(inverse));
  defaultPrec->initializeUnspecified(inverseOp);
}

void MumpsPreconditionerFactory::uninitializePrec(Thyra::PreconditionerBase<double> *prec,
                                                  Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> *fwdOpSrc,
                                                  Thyra::ESupportSolveUse *supportSolveUse) const {
  auto *defaultPrec = dynamic_cast<Thyra::DefaultPreconditioner<double> *>(prec);
  if (defaultPrec) defaultPrec->uninitialize();
  if (fwdOpSrc) *fwdOpSrc = Teuchos::null;
  if (supportSolveUse) *supportSolveUse = Thyra::SUPPORT_SOLVE_UNSPECIFIED;
}

void MumpsPreconditionerFactory::setParameterList(const Teuchos::RCP<Teuchos::ParameterList> &paramList) {
  paramList->validateParametersAndSetDefaults(*getValidParameters());
  params_ = paramList;
}

Teuchos::RCP<Teuchos::ParameterList> MumpsPreconditionerFactory::unsetParameterList() {
  auto old = params_;
  params_ = Teuchos::null;
  return old;
}

Teuchos::RCP<const Teuchos::ParameterList> MumpsPreconditionerFactory::getValidParameters() const {
  static const auto valid = [] {
    auto p = Teuchos::rcp(new Teuchos::ParameterList("MUMPS"));
    p->set("symmetric", true, "the tangent is symmetric: LDL^T of one triangle (else LU)");
    p->set("reuse iterations", 0,
           "0: refactor for every tangent; k > 0: keep the factors within a Newton solve while a solve "
           "takes at most k Krylov iterations");
    p->set("reuse scope", std::string("Newton solve"),
           "how long kept factors live: Newton solve, step (beginStep) or run",
           Teuchos::rcp(new Teuchos::StringValidator(Teuchos::tuple<std::string>("Newton solve", "step", "run"))));
    p->set("ordering", std::string("auto"),
           "the fill-reducing ordering: auto (PORD from 1,000 unknowns, MUMPS's own choice below), PORD, AMD, AMF or QAMD",
           Teuchos::rcp(new Teuchos::StringValidator(Teuchos::tuple<std::string>("auto", "PORD", "AMD", "AMF", "QAMD"))));
    p->set("gathered", false,
           "on several ranks: factor on rank 0 alone, the entries gathered there (the same answer bit for "
           "bit run after run); otherwise every rank takes part");
    return p;
  }();
  return valid;
}

} // namespace glossa::solvers
