#include "solvers/control/ControlStepResult.hpp"

#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace glossa::solvers {

bool ControlStepResult::found() const { return std::isfinite(objective); }

namespace {
// One list of fields per struct serves both directions, so that what is read is what was
// written. `R` is the struct, const when writing.
template <class Io, class R> void newtonFields(Io &io, R &n) {
  io(n.converged);
  io(n.elementInverted);
  io(n.iterations);
  io(n.linearIterations);
  io(n.residualNorms);
  io(n.linearIterationsPerStep);
  io(n.failure);
}

template <class Io, class R> void uzawaFields(Io &io, R &r) {
  io(r.converged);
  io(r.elementInverted);
  io(r.solves);
  io(r.newtonIterations);
  io(r.linearIterations);
  io(r.dilatation.max);
  io(r.dilatation.mean);
  io(r.dilatation.maxVolumeChange);
  io(r.newton);
}

template <class Io, class R> void resultFields(Io &io, R &r) {
  io(r.inputs);
  io(r.evaluated);
  io(r.objective);
  io(r.candidates);
  io(r.generations);
  io(r.iterations);
  io(r.sensitivities);
  io(r.sensitivityKrylov);
  io(r.sensitivityCheck);
  io(r.failedCandidates);
  io(r.screenedCandidates);
  io(r.solvedAgainCandidates);
  io(r.firstFailure);
  io(r.stop);
  io(r.pointErrors);
  io(r.solve);
  io(r.couplingIterations);
  io(r.couplingChange);
}

// Counts, flags and characters are stored as doubles: exact below 2^53. A sequence is its
// length, then its elements.
class FlatWriter {
public:
  explicit FlatWriter(std::vector<double> &buffer) : buffer_(buffer) {}
  template <class T> std::enable_if_t<std::is_arithmetic_v<T>> operator()(const T &v) {
    buffer_.push_back(static_cast<double>(v));
  }
  template <class T> void operator()(const std::vector<T> &values) { sequence(values); }
  void operator()(const std::string &text) { sequence(text); }
  void operator()(const Eigen::VectorXd &v) { sequence(v); }
  void operator()(const NewtonResult &n) { newtonFields(*this, n); }
  void operator()(const UzawaResult &r) { uzawaFields(*this, r); }

private:
  template <class Sequence> void sequence(const Sequence &values) {
    (*this)(static_cast<std::size_t>(values.size()));
    for (const auto &v : values) (*this)(v);
  }
  std::vector<double> &buffer_;
};

class FlatReader {
public:
  FlatReader(const std::vector<double> &buffer, std::size_t &position) : buffer_(buffer), k_(position) {}
  template <class T> std::enable_if_t<std::is_arithmetic_v<T>> operator()(T &v) { v = static_cast<T>(next()); }
  template <class T> void operator()(std::vector<T> &values) { sequence(values); }
  void operator()(std::string &text) { sequence(text); }
  void operator()(Eigen::VectorXd &v) { sequence(v); }
  void operator()(NewtonResult &n) { newtonFields(*this, n); }
  void operator()(UzawaResult &r) { uzawaFields(*this, r); }

private:
  double next() {
    if (k_ >= buffer_.size()) throw std::runtime_error("control step result: the buffer ends early");
    return buffer_[k_++];
  }
  template <class Sequence> void sequence(Sequence &values) {
    std::size_t size = 0;
    (*this)(size);
    values.resize(static_cast<decltype(values.size())>(size));
    for (auto &v : values) (*this)(v);
  }
  const std::vector<double> &buffer_;
  std::size_t &k_;
};
} // namespace

void appendControlStepResult(const ControlStepResult &result, std::vector<double> &buffer) {
  FlatWriter out(buffer);
  resultFields(out, result);
}

ControlStepResult readControlStepResult(const std::vector<double> &buffer, std::size_t &position) {
  FlatReader in(buffer, position);
  ControlStepResult result;
  resultFields(in, result);
  return result;
}

} // namespace glossa::solvers
