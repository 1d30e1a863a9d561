#include "workloads/dynamics/subtask_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

#include "workloads/dynamics/state.hpp"
#include "workloads/dynamics/term_sweep.hpp"

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
  std::vector<std::vector<Folded<double>>> values;  // [sample][term]
  for (int s = 0; s < kZeroSamples; ++s) {
    const auto input = make_worker_input<double>(model, random_configuration(model, rng));
    values.push_back(evaluate_terms(model, terms, input));
  }
  std::vector<TermMagnitude> result;
  std::map<TermKind, double> scale;
  for (std::size_t t = 0; t < terms.size(); ++t) {
    TermMagnitude m{terms[t]};
    m.structural = values.front()[t].is_zero();  // the same for every configuration
    if (!m.structural)
      for (const std::vector<Folded<double>>& sample : values)
        m.max_abs = std::max(m.max_abs, std::abs(sample[t].value()));
    scale[m.term.kind] = std::max(scale[m.term.kind], m.max_abs);
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

}  // namespace

// With the last link's axial inertia set to zero, the Coriolis terms of the last joint that vanish
// are dropped (they are proportional to that small inertia); their size comes from the robot as it
// is.
PaperSimplification paper_simplification(const RobotModel& model) {
  const std::vector<TermMagnitude> analysis = analyse_terms(model, all_terms());
  std::vector<TermMagnitude> present;
  std::vector<Subtask> coriolis;  // only these can be dropped
  for (const TermMagnitude& m : analysis) {
    if (m.zero) continue;
    present.push_back(m);
    if (m.term.kind == TermKind::coriolis) coriolis.push_back(m.term);
  }
  const int last = kJoints - 1;
  RobotModel simplified = model;
  simplified.joints[last].link.inertia.z() = 0;
  // Analysed together: the zero threshold is relative to the scale of all the Coriolis terms.
  const std::vector<TermMagnitude> without = analyse_terms(simplified, coriolis);
  PaperSimplification p;
  p.smallest_kept = std::numeric_limits<double>::infinity();
  std::size_t c = 0;  // the next Coriolis term's verdict in `without`
  for (const TermMagnitude& m : present) {
    const bool is_coriolis = m.term.kind == TermKind::coriolis;
    if (is_coriolis && without[c++].zero && involves(m.term, last)) {
      p.dropped.push_back(m.term);
      p.largest_dropped = std::max(p.largest_dropped, m.max_abs);
      continue;
    }
    p.kept.push_back(m.term);
    if (is_coriolis) p.smallest_kept = std::min(p.smallest_kept, m.max_abs);
  }
  if (std::isinf(p.smallest_kept)) p.smallest_kept = 0;
  return p;
}

std::string PaperSimplification::refusal(const std::string& robot) const {
  std::ostringstream out;
  out.precision(2);
  out << "model \"paper\" does not fit " << robot
      << ": the paper's simplification (derived for the Stanford arm) drops the Coriolis terms of "
         "joint "
      << kJoints << " that vanish when link " << kJoints << "'s axial inertia Izz is zero ("
      << dropped.size() << " terms here, up to " << std::scientific << largest_dropped
      << "), assuming they are negligible, at most " << std::defaultfloat << kNegligible
      << " times every Coriolis term it keeps; here the smallest kept term is only "
      << std::scientific << smallest_kept
      << ". Use model \"full\", every non-zero term (workload.model in a scene, --model for "
         "`t800sim "
         "dynamics`)";
  return out.str();
}

std::vector<Subtask> derive_subtasks(const RobotModel& model, ModelVariant variant) {
  if (variant == ModelVariant::full) return nonzero(analyse_terms(model, all_terms()));
  PaperSimplification p = paper_simplification(model);
  if (!p.holds())
    throw std::invalid_argument(
        p.refusal(model.name.empty() ? "this robot" : "the robot '" + model.name + "'"));
  return std::move(p.kept);
}

}  // namespace dynamics
