// Test matrices for `t800sim stress`: random orthogonal factors, prescribed condition numbers, and
// well-conditioned matrices whose elimination without interchanges meets a tiny pivot.
#pragma once

#include <random>

#include <Eigen/Core>

namespace tools::stress {

// Q from the QR factorisation of a Gaussian matrix, columns signed so that R has a positive
// diagonal: uniformly distributed over the orthogonal group (Mezzadri 2007).
Eigen::MatrixXd random_orthogonal(int n, std::mt19937_64& rng);

// U Σ Vᵀ (nonsymmetric) or Q Σ Qᵀ (symmetric positive definite) with singular values spaced
// geometrically from 1 down to 1/condition: the 2-norm condition number is `condition`.
Eigen::MatrixXd with_condition(int n, double condition, bool spd, std::mt19937_64& rng);

// `a` with a_kk changed so that the k-th pivot of elimination without interchanges is
// delta * max|a_ij| (in exact arithmetic; a_kk enters only that pivot's Schur complement).
// delta = 0 makes the leading (k+1) x (k+1) block singular while `a` stays regular.
Eigen::MatrixXd with_tiny_pivot(const Eigen::MatrixXd& a, int k, double delta);

// The 2-norm condition number (singular values by Jacobi SVD).
double condition_number(const Eigen::MatrixXd& a);

}  // namespace tools::stress
