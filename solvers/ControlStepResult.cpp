#include "solvers/ControlStepResult.hpp"

#include <cmath>
#include <stdexcept>

namespace glossa::solvers {

bool ControlStepResult::found() const { return std::isfinite(objective); }

namespace {
// Counts, flags and characters are stored as doubles: exact below 2^53. A sequence is its
// length, then its elements.
class FlatWriter {
public:
  explicit FlatWriter(std::vector<double> &buffer) : buffer_(buffer) {}
  void number(double v) { buffer_.push_back(v); }
  template <class Sequence> void sequence(const Sequence &values) {
    number(static_cast<double>(values.size()));
    for (const auto v : values) number(static_cast<double>(v));
  }

private:
  std::vector<double> &buffer_;
};

class FlatReader {
public:
  FlatReader(const std::vector<double> &buffer, std::size_t &position) : buffer_(buffer), k_(position) {}
  double number() {
    if (k_ >= buffer_.size()) throw std::runtime_error("control step result: the buffer ends early");
    return buffer_[k_++];
  }
  template <class T> T whole() { return static_cast<T>(number()); }
  template <class Sequence> Sequence sequence() {
    Sequence values(whole<std::size_t>(), typename Sequence::value_type{});
    for (auto &v : values) v = static_cast<typename Sequence::value_type>(number());
    return values;
  }

private:
  const std::vector<double> &buffer_;
  std::size_t &k_;
};

void write(FlatWriter &out, const NewtonResult &n) {
  out.number(n.converged);
  out.number(n.elementInverted);
  out.number(n.iterations);
  out.number(n.linearIterations);
  out.sequence(n.residualNorms);
  out.sequence(n.linearIterationsPerStep);
  out.sequence(n.failure);
}

NewtonResult readNewton(FlatReader &in) {
  NewtonResult n;
  n.converged = in.number() != 0.0;
  n.elementInverted = in.number() != 0.0;
  n.iterations = in.whole<int>();
  n.linearIterations = in.whole<int>();
  n.residualNorms = in.sequence<std::vector<double>>();
  n.linearIterationsPerStep = in.sequence<std::vector<int>>();
  n.failure = in.sequence<std::string>();
  return n;
}

void write(FlatWriter &out, const UzawaResult &r) {
  out.number(r.converged);
  out.number(r.elementInverted);
  out.number(r.solves);
  out.number(r.newtonIterations);
  out.number(r.linearIterations);
  out.number(r.dilatation.max);
  out.number(r.dilatation.mean);
  out.number(r.dilatation.maxVolumeChange);
  out.number(static_cast<double>(r.newton.size()));
  for (const auto &n : r.newton) write(out, n);
}

UzawaResult readUzawa(FlatReader &in) {
  UzawaResult r;
  r.converged = in.number() != 0.0;
  r.elementInverted = in.number() != 0.0;
  r.solves = in.whole<int>();
  r.newtonIterations = in.whole<int>();
  r.linearIterations = in.whole<int>();
  r.dilatation.max = in.number();
  r.dilatation.mean = in.number();
  r.dilatation.maxVolumeChange = in.number();
  r.newton.resize(in.whole<std::size_t>());
  for (auto &n : r.newton) n = readNewton(in);
  return r;
}
} // namespace

void appendControlStepResult(const ControlStepResult &result, std::vector<double> &buffer) {
  FlatWriter out(buffer);
  out.sequence(result.inputs);
  out.sequence(result.evaluated);
  out.number(result.objective);
  out.number(static_cast<double>(result.candidates));
  out.number(result.generations);
  out.number(result.iterations);
  out.number(result.sensitivities);
  out.number(result.sensitivityKrylov);
  out.number(result.sensitivityCheck);
  out.sequence(result.stop);
  out.sequence(std::vector<double>(result.pointErrors.data(), result.pointErrors.data() + result.pointErrors.size()));
  write(out, result.solve);
}

ControlStepResult readControlStepResult(const std::vector<double> &buffer, std::size_t &position) {
  FlatReader in(buffer, position);
  ControlStepResult result;
  result.inputs = in.sequence<std::vector<double>>();
  result.evaluated = in.sequence<std::vector<int>>();
  result.objective = in.number();
  result.candidates = in.whole<std::size_t>();
  result.generations = in.whole<int>();
  result.iterations = in.whole<int>();
  result.sensitivities = in.whole<int>();
  result.sensitivityKrylov = in.whole<int>();
  result.sensitivityCheck = in.number();
  result.stop = in.sequence<std::string>();
  const auto errors = in.sequence<std::vector<double>>();
  result.pointErrors = Eigen::Map<const Eigen::VectorXd>(errors.data(), static_cast<Eigen::Index>(errors.size()));
  result.solve = readUzawa(in);
  return result;
}

} // namespace glossa::solvers
