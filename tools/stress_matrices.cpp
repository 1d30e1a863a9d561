#include "tools/stress_matrices.hpp"

#include <cmath>

#include <Eigen/QR>
#include <Eigen/SVD>

namespace tools::stress {

Eigen::MatrixXd random_orthogonal(int n, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd g(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) g(i, j) = normal(rng);
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(g);
  Eigen::MatrixXd q = qr.householderQ();
  const Eigen::MatrixXd r = qr.matrixQR().triangularView<Eigen::Upper>();
  for (int j = 0; j < n; ++j)
    if (r(j, j) < 0) q.col(j) = -q.col(j);
  return q;
}

Eigen::MatrixXd with_condition(int n, double condition, bool spd, std::mt19937_64& rng) {
  Eigen::VectorXd sigma(n);
  for (int i = 0; i < n; ++i)
    sigma(i) = n == 1 ? 1.0 : std::pow(condition, -double(i) / double(n - 1));
  const Eigen::MatrixXd u = random_orthogonal(n, rng);
  const Eigen::MatrixXd v = spd ? u : random_orthogonal(n, rng);
  Eigen::MatrixXd a = u * sigma.asDiagonal() * v.transpose();
  if (spd) a = 0.5 * (a + a.transpose()).eval();  // exactly symmetric after rounding
  return a;
}

Eigen::MatrixXd with_tiny_pivot(const Eigen::MatrixXd& a, int k, double delta) {
  using MatrixL = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  MatrixL s = a.cast<long double>();
  // Elimination without interchanges up to step k; s(k, k) is then the k-th pivot.
  for (int j = 0; j < k; ++j)
    for (int i = j + 1; i < s.rows(); ++i) {
      const long double l = s(i, j) / s(j, j);
      s.row(i).tail(s.cols() - j) -= l * s.row(j).tail(s.cols() - j);
    }
  Eigen::MatrixXd out = a;
  const long double target = delta * static_cast<long double>(a.cwiseAbs().maxCoeff());
  out(k, k) = double(static_cast<long double>(a(k, k)) - (s(k, k) - target));
  return out;
}

double condition_number(const Eigen::MatrixXd& a) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a);
  const Eigen::VectorXd& s = svd.singularValues();
  return s(s.size() - 1) > 0 ? s(0) / s(s.size() - 1) : std::numeric_limits<double>::infinity();
}

}  // namespace tools::stress
