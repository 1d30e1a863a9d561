// Which subtasks a model needs, derived from the model (never typed in): a structural-zero analysis
// keeps every term that is not identically zero over the configuration space (`full`); the paper's
// simplification then drops the Coriolis terms involving the last joint that vanish when the last
// link's axial inertia Izz is zero (`paper`; 17 D + 43 C + 4 h = 64 for the Stanford arm, as in the
// paper).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "workloads/dynamics/robot_model.hpp"
#include "workloads/dynamics/subtask.hpp"

namespace dynamics {

enum class ModelVariant { full, paper };

const char* to_string(ModelVariant variant);
std::optional<ModelVariant> parse_model_variant(const std::string& text);  // "full" or "paper"

// D terms first (i <= j), then C (i, then j <= k), then h, each in index order. `paper` throws
// std::invalid_argument when the paper's simplification does not hold for this robot (see below).
std::vector<Subtask> derive_subtasks(const RobotModel& model, ModelVariant variant);

// The paper's simplification, derived for the robot at hand: the Coriolis terms of the last joint
// that vanish when the last link's axial inertia Izz is zero are dropped. It assumes those terms
// are negligible beside every Coriolis term it keeps; it holds when the largest dropped term is at
// most kNegligible times the smallest kept one (over the sampled configurations). For the
// Stanford arm the dropped terms are about 1.5e-4 and the kept ones at least 0.7 (a factor of
// about 5000); for Corke's PUMA 560 they are 2e-5 against 1e-4, and the paper model is refused.
constexpr double kNegligible = 1e-2;

struct PaperSimplification {
  std::vector<Subtask> kept;     // the paper model's subtasks
  std::vector<Subtask> dropped;  // Coriolis terms of the last joint left out
  double largest_dropped = 0;    // max |value| of a dropped term
  double smallest_kept = 0;      // max |value| of the smallest kept Coriolis term (0: none kept)
  bool holds() const { return dropped.empty() || largest_dropped <= kNegligible * smallest_kept; }
  // Why the paper model does not fit `robot`, naming its assumption and the figures.
  std::string refusal(const std::string& robot) const;
};

PaperSimplification paper_simplification(const RobotModel& model);

// The analysis underneath. A term is identically zero when its kernel folds it to a structural zero
// for the model's constants, or when max |value| over kZeroSamples configurations drawn uniformly
// inside the joint limits (fixed seed) is at most kRelativeZero times the largest |value| of any
// term of its kind. Round-off leaves ~1e-16 of the scale where terms cancel exactly; the smallest
// genuine terms of the Stanford arm (Coriolis terms proportional to Izz6 = 3e-4) are ~1e-5 of the
// scale.
constexpr int kZeroSamples = 64;
constexpr double kRelativeZero = 1e-12;

struct TermMagnitude {
  Subtask term;
  double max_abs = 0;       // over the sampled configurations
  bool structural = false;  // folded to zero by the model's constants
  bool zero = false;        // the verdict
};

std::vector<TermMagnitude> analyse_terms(const RobotModel& model,
                                         const std::vector<Subtask>& terms);

}  // namespace dynamics
