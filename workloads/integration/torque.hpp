// Joint torques for a trajectory: zero (passive), a table read from a CSV file, or a PD controller
// to a target. All in double: the trajectory rounds τ to its precision where it forms the
// right-hand side, exactly as elimination::dynamics_system does.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "workloads/dynamics/robot_model.hpp"

namespace integration {

// How a torque table is read between its rows: linearly interpolated, or held from the last row
// at or before t (zero-order hold). Before the first row the first row holds, after the last the
// last.
enum class TorqueInterpolation { linear, hold };

// A table of τ(t): CSV with a header line `t,tau1,...,tau6`, then one row per time, t strictly
// increasing. Blank lines and lines starting with '#' are skipped.
class TorqueTable {
 public:
  // Errors are std::invalid_argument naming `name:line`. Reading the file is the caller's: what may
  // be read as input is the simulator's rule (network/input_file.hpp), not the numerics'.
  static TorqueTable parse(std::istream& in, const std::string& name, TorqueInterpolation how);

  dynamics::JointVector at(double t) const;
  std::size_t rows() const { return t_.size(); }

 private:
  std::vector<double> t_;
  std::vector<dynamics::JointVector> tau_;
  TorqueInterpolation how_ = TorqueInterpolation::linear;
};

// τ = kp ∘ (target − q) − kd ∘ q̇, joint by joint.
struct PdGains {
  dynamics::JointVector kp = dynamics::JointVector::Zero();
  dynamics::JointVector kd = dynamics::JointVector::Zero();
  dynamics::JointVector target = dynamics::JointVector::Zero();
};

template <class S>
dynamics::JointVectorT<S> pd_torque(const PdGains& g, const dynamics::JointVectorT<S>& q,
                                    const dynamics::JointVectorT<S>& qd) {
  dynamics::JointVectorT<S> tau;
  for (int i = 0; i < dynamics::kJoints; ++i)
    tau(i) = S(g.kp(i)) * (S(g.target(i)) - q(i)) - S(g.kd(i)) * qd(i);
  return tau;
}

}  // namespace integration
