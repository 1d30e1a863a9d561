#include "workloads/dynamics/subtask_set.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "workloads/dynamics/evaluate.hpp"

namespace dynamics {

const char* to_string(ModelVariant variant) {
  return variant == ModelVariant::full ? "full" : "paper";
}

std::optional<ModelVariant> parse_model_variant(const std::string& text) {
  if (text == "full") return ModelVariant::full;
  if (text == "paper") return ModelVariant::paper;
  return std::nullopt;
}

std::vector<TermMagnitude> analyse_terms(const RobotModel& model,
                                         const std::vector<Subtask>& terms) {
  std::mt19937_64 rng(0x7800);  // fixed: the derived sets must not change from run to run
  std::vector<WorkerInput<double>> samples;
  for (int s = 0; s < kZeroSamples; ++s) {
    samples.push_back(make_worker_input<double>(model, random_configuration(model, rng)));
  }
  std::vector<TermMagnitude> result;
  std::map<TermKind, double> scale;
  for (const Subtask& term : terms) {
    TermMagnitude m{term};
    for (const WorkerInput<double>& input : samples) {
      const Folded<double> value = evaluate_term(model, term, input);
      m.structural = value.is_zero();
      if (m.structural) break;  // the same for every configuration
      m.max_abs = std::max(m.max_abs, std::abs(value.value()));
    }
    scale[term.kind] = std::max(scale[term.kind], m.max_abs);
    result.push_back(m);
  }
  for (TermMagnitude& m : result) {
    m.zero = m.structural || m.max_abs <= kRelativeZero * scale[m.term.kind];
  }
  return result;
}

namespace {

std::vector<Subtask> nonzero(const std::vector<TermMagnitude>& analysis) {
  std::vector<Subtask> kept;
  for (const TermMagnitude& m : analysis) {
    if (!m.zero) kept.push_back(m.term);
  }
  return kept;
}

bool involves(const Subtask& term, int joint) {
  return term.i == joint || term.j == joint || term.k == joint;
}

// The paper's simplified form: with the last link's axial inertia set to zero, the Coriolis terms
// of the last joint that vanish are dropped (they are proportional to that small inertia).
std::vector<Subtask> simplify(const RobotModel& model, const std::vector<Subtask>& full) {
  const int last = kJoints - 1;
  RobotModel simplified = model;
  simplified.joints[last].link.inertia.z() = 0;
  // Analysed together with all the other terms: the zero threshold is relative to each kind's
  // scale.
  std::vector<Subtask> kept;
  for (const TermMagnitude& m : analyse_terms(simplified, full)) {
    const bool dropped = m.zero && m.term.kind == TermKind::coriolis && involves(m.term, last);
    if (!dropped) kept.push_back(m.term);
  }
  return kept;
}

}  // namespace

std::vector<Subtask> derive_subtasks(const RobotModel& model, ModelVariant variant) {
  const std::vector<Subtask> full = nonzero(analyse_terms(model, all_terms()));
  return variant == ModelVariant::full ? full : simplify(model, full);
}

}  // namespace dynamics
