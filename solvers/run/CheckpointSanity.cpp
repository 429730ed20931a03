#include "solvers/run/CheckpointSanity.hpp"

#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <string>
#include <system_error>

#include "io/output/CheckpointError.hpp"

namespace glossa::solvers {

namespace {

using nlohmann::json;

// The shortest text that reads back as `x` (0.6, not 0.59999999999999998; nan and inf as such).
std::string text(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

[[noreturn]] void refuse(const std::string &what) { throw io::CheckpointError(what); }

const json &member(const json &j, const std::string &where, const char *key) {
  if (!j.is_object() || !j.contains(key)) refuse(where + " has no '" + key + "'");
  return j.at(key);
}

// A finite number in [lo, hi] (`open`: lo excluded), named `name` in the message with `why`.
double number(const json &j, const std::string &name, double lo, double hi, bool open, const std::string &why) {
  if (!j.is_number()) refuse(name + " is " + std::string(j.type_name()) + ", not a number");
  const double x = j.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi || (open && x == lo))
    refuse(name + " = " + text(x) + "; it must be finite and in " + (open ? "(" : "[") + text(lo) + ", " + text(hi) +
           "]" + (why.empty() ? "" : " (" + why + ")"));
  return x;
}

long long count(const json &j, const std::string &name, long long most = INT_MAX) {
  if (!j.is_number_integer() || j.get<long long>() < 0 || j.get<long long>() > most)
    refuse(name + " = " + j.dump() + "; it must be a whole number in [0, " + std::to_string(most) + "]");
  return j.get<long long>();
}

// An array of `size` finite numbers in [lo, hi] (`size` SIZE_MAX: any length).
void values(const json &j, const std::string &name, std::size_t size, double lo, double hi, const std::string &why = "") {
  if (!j.is_array()) refuse(name + " is " + std::string(j.type_name()) + ", not an array");
  if (size != SIZE_MAX && j.size() != size)
    refuse(name + " has " + std::to_string(j.size()) + " values, this run has " + std::to_string(size) +
           " here (another mesh or partition)");
  for (std::size_t i = 0; i < j.size(); ++i) number(j[i], name + "[" + std::to_string(i) + "]", lo, hi, false, why);
}

void checkLimitPoint(const json &limit) {
  number(member(limit, "limit_point", "reference"), "limit_point/reference", -HUGE_VAL, HUGE_VAL, false, "");
  number(member(limit, "limit_point", "last"), "limit_point/last", -HUGE_VAL, HUGE_VAL, false, "");
  if (!limit.contains("bracket")) return;
  const json &b = limit.at("bracket");
  values(b, "limit_point/bracket", 4, -HUGE_VAL, HUGE_VAL);
  if (b[0].get<double>() > b[1].get<double>()) refuse("limit_point/bracket's lower end is above its upper end");
  number(b[3], "limit_point/bracket's node", 0.0, 1e15, false, "a node number");
}

// The files' lengths must still be there to cut back to: a restart never lengthens a file.
void checkOutputs(const json &outputs, double t, const CheckpointShape &shape) {
  const json &csv = member(outputs, "outputs", "csv_bytes");
  if (!csv.is_object()) refuse("outputs/csv_bytes is not an object");
  for (const auto &item : csv.items()) {
    const std::string file = item.key();
    const json &bytes = item.value();
    const std::filesystem::path name(file);
    if (name.filename() != name || file.empty() || file == "." || file == "..")
      refuse("outputs/csv_bytes names '" + file + "', not a file of the output directory");
    const long long at = count(bytes, "outputs/csv_bytes/" + file, LLONG_MAX);
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(shape.outputDirectory / name, error);
    if (error || size < static_cast<std::uintmax_t>(at))
      refuse("it records " + file + " at " + std::to_string(at) + " bytes, and " +
             (shape.outputDirectory / name).string() + " is " +
             (error ? "missing" : "only " + std::to_string(size) + " bytes long") + " (not this directory's checkpoint?)");
  }
  const json &steps = member(outputs, "outputs", "field_steps");
  if (!steps.is_array()) refuse("outputs/field_steps is not an array");
  if (steps.size() > static_cast<std::size_t>(shape.step) + 1)
    refuse("outputs/field_steps lists " + std::to_string(steps.size()) + " field steps after step " +
           std::to_string(shape.step) + " (at most one per step and the reference state)");
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const std::string name = "outputs/field_steps[" + std::to_string(k) + "]";
    number(member(steps[k], name, "time"), name + "/time", 0.0, t, false, "written by the time of the checkpoint");
    if (!member(steps[k], name, "attributes").is_array()) refuse(name + "/attributes is not an array");
  }
}

// The summary's steps are the committed ones: as many as the step number, the last at its time.
void checkSummary(const json &summary, long long step, double t) {
  if (!summary.is_object()) refuse("summary is " + std::string(summary.type_name()) + ", not an object");
  if (!summary.contains("steps")) return;
  const json &steps = summary.at("steps");
  if (!steps.is_array() || steps.size() != static_cast<std::size_t>(step))
    refuse("summary/steps lists " + (steps.is_array() ? std::to_string(steps.size()) : std::string("no")) +
           " steps, the checkpoint is after step " + std::to_string(step));
  if (steps.empty()) return;
  const double last = number(member(steps.back(), "summary/steps' last", "time"), "summary/steps' last time",
                             -HUGE_VAL, HUGE_VAL, false, "");
  if (last != t) refuse("summary/steps' last time is " + text(last) + " s, the checkpoint's time " + text(t) + " s");
}

} // namespace

void checkRunValues(const json &run, const CheckpointShape &shape) {
  if (!run.is_object()) refuse("the run part is " + std::string(run.type_name()) + ", not an object");
  if (!member(run, "run", "deck").is_string()) refuse("run/deck is not text");
  count(member(run, "run", "ranks"), "run/ranks");
  count(member(run, "run", "control_groups"), "run/control_groups");
  const long long step = count(member(run, "run", "step"), "step");
  if (step != shape.step)
    refuse("step = " + std::to_string(step) + ", and the checkpoint is named after step " + std::to_string(shape.step));
  // The last step ends at t + (end - t), which may round one unit past the end time: allowed with
  // the same relative margin as the load stepper's test of whether the run is finished.
  const json &time = member(run, "run", "time");
  const bool roundedPastEnd = time.is_number() && time.get<double>() > shape.endTime &&
                              time.get<double>() <= shape.endTime * (1.0 + 1e-12);
  const double t = roundedPastEnd ? time.get<double>() : number(time, "time", 0.0, shape.endTime, false, "Time/end time");
  number(member(run, "run", "previous_dt"), "previous_dt", 0.0, t, false, "no longer than the time so far");
  const json &steps = member(run, "run", "step_size");
  if (!steps.is_array() || steps.size() != 2) refuse("step_size is not [step size, successes]");
  // A committed step size is never cut below the minimum (the run stops instead) nor raised above
  // the deck's step; a step size of 0 would never end the run.
  number(steps[0], "the step size", shape.minimumStep, shape.nominalStep, shape.minimumStep <= 0.0,
         "Time/minimum step size to Time/step size");
  count(steps[1], "the step size's successes");
  values(member(run, "run", "penalty_ratios"), "penalty_ratios", shape.tissues, 0.0, HUGE_VAL);
  for (const auto &r : run.at("penalty_ratios"))
    if (r.get<double>() <= 0.0) refuse("a penalty ratio is " + text(r.get<double>()) + "; they are positive");
  if (!member(run, "run", "softening_said").is_boolean()) refuse("softening_said is not true or false");
  if (run.contains("limit_point")) checkLimitPoint(run.at("limit_point"));
  // The controller's memory: the inputs of the last two found steps (none yet before the first)
  // and the committed mean fibre stretches its pruning compares against.
  if (run.contains("control_memory")) {
    const json &memory = run.at("control_memory");
    if (!memory.is_array() || memory.size() != 2) refuse("control_memory is not the inputs of two steps");
    values(memory[0], "control_memory[0]", SIZE_MAX, -HUGE_VAL, HUGE_VAL);
    values(memory[1], "control_memory[1]", SIZE_MAX, -HUGE_VAL, HUGE_VAL);
  }
  if (run.contains("committed_stretch"))
    values(run.at("committed_stretch"), "committed_stretch", SIZE_MAX, 0.0, HUGE_VAL, "a stretch");
  checkOutputs(member(run, "run", "outputs"), t, shape);
  checkSummary(member(run, "run", "summary"), step, t);
}

void checkPartValues(const json &part, double time, const CheckpointShape &shape) {
  if (!part.is_object()) refuse("the part is " + std::string(part.type_name()) + ", not an object");
  values(member(part, "part", "u"), "u (displacement)", shape.displacements, -HUGE_VAL, HUGE_VAL);
  values(member(part, "part", "lambda"), "lambda (multipliers)", shape.elements, -HUGE_VAL, HUGE_VAL);
  if (part.contains("previous_u") || part.contains("previous_lambda")) {
    values(member(part, "part", "previous_u"), "previous_u", shape.displacements, -HUGE_VAL, HUGE_VAL);
    values(member(part, "part", "previous_lambda"), "previous_lambda", shape.elements, -HUGE_VAL, HUGE_VAL);
  }
  if (part.contains("multiplier_prediction")) {
    const json &p = part.at("multiplier_prediction");
    for (const char *key : {"last", "before_last"}) {
      const json &v = member(p, "multiplier_prediction", key);
      values(v, std::string("multiplier_prediction/") + key, v.is_array() && v.empty() ? 0 : shape.elements, -HUGE_VAL,
             HUGE_VAL);
    }
    number(member(p, "multiplier_prediction", "last_dt"), "multiplier_prediction/last_dt", 0.0, HUGE_VAL, false, "");
  }
  if (shape.dynamic) {
    const json &inertia = member(part, "part", "inertia");
    for (const char *key : {"u", "v", "a", "g"})
      values(member(inertia, "inertia", key), std::string("inertia/") + key, shape.displacements, -HUGE_VAL, HUGE_VAL);
  }
  const json &muscle = member(part, "part", "muscle");
  values(member(muscle, "muscle", "lambda_c"), "muscle/lambda_c", shape.lambdaC, 0.0, HUGE_VAL, "a stretch");
  for (const auto &l : muscle.at("lambda_c"))
    if (l.get<double>() == 0.0) refuse("a contractile stretch in muscle/lambda_c is 0; stretches are positive");
  values(member(muscle, "muscle", "alpha"), "muscle/alpha", shape.groups, 0.0, 1.0, "an activation");
  values(member(muscle, "muscle", "input"), "muscle/input", shape.groups, 0.0, 1.0, "a neural input");
  const json &external = member(muscle, "muscle", "external_lambda_c");
  if (!external.is_array() || external.size() != shape.externalLambdaC.size())
    refuse("muscle/external_lambda_c is not one array per external muscle (" +
           std::to_string(shape.externalLambdaC.size()) + ")");
  for (std::size_t m = 0; m < external.size(); ++m)
    values(external[m], "muscle/external_lambda_c[" + std::to_string(m) + "]", shape.externalLambdaC[m], 0.0, HUGE_VAL,
           "a stretch");
  const double t = number(member(muscle, "muscle", "time"), "muscle/time", 0.0, HUGE_VAL, false, "");
  if (t != time) refuse("muscle/time is " + text(t) + " s, the checkpoint's time " + text(time) + " s");
  number(member(muscle, "muscle", "dt"), "muscle/dt", 0.0, HUGE_VAL, true, "a step size");
  if (shape.contactPoints.empty() && !part.contains("contact")) return;
  const json &contacts = member(part, "part", "contact");
  if (!contacts.is_array() || contacts.size() != shape.contactPoints.size())
    refuse("contact is not one entry per contact (" + std::to_string(shape.contactPoints.size()) + ")");
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const std::string name = "contact[" + std::to_string(c) + "]";
    values(member(contacts[c], name, "multipliers"), name + "/multipliers", shape.contactPoints[c], 0.0, HUGE_VAL,
           "a contact pressure");
    values(member(contacts[c], name, "anchors"), name + "/anchors", 3 * shape.contactPoints[c], -HUGE_VAL, HUGE_VAL,
           "a position");
    values(member(contacts[c], name, "anchored"), name + "/anchored", shape.contactPoints[c], 0.0, 1.0, "0 or 1");
    values(member(contacts[c], name, "slip"), name + "/slip", shape.contactPoints[c], 0.0, HUGE_VAL, "a slip length");
  }
}

} // namespace glossa::solvers
