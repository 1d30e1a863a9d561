// A systolic matrix product C = A.B on a g x g grid of transputers (4 x 4 by default), blocks of
// b x b elements: cell (i, j) owns block C(i, j); blocks of A flow left to right along the rows,
// blocks of B top to bottom down the columns; the left column holds A's block rows, the top row
// B's block columns. At step k every cell multiplies A(i, k) by B(k, j) into its C block while, in
// PAR, it passes both on and takes the next ones in -- the links move blocks while the FPU
// multiplies, as occam's PAR of communications and arithmetic lets a transputer do.
//
//   SEQ k = 0 FOR g
//     PAR
//       IF k < g-1: left ? a.next, up ? b.next   -- (the edge cells read their own arrays)
//       right ! a, down ! b                      -- (not off the grid)
//       C := C + a.b                             -- BLOCK.MAC, timed from its T800 code
//     a, b := a.next, b.next
//
// `overlap = false` runs the communications and the multiply one after the other instead, to show
// what the overlap gains.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>

#include "programs/support/checksum.hpp"
#include "programs/systolic/block_product.hpp"
#include "t800sim/workload.hpp"

namespace systolic {

namespace {

using namespace t800sim;

template <class S>
class Systolic : public Program {
  using Value = typename S::value_type;  // float or double: what the blocks hold
  using Wire = Block<std::conditional_t<std::is_same_v<Value, float>, REAL32, REAL64>>;
  using Values = std::vector<Value>;

 public:
  Systolic(const Params& p, const Network& n)
      : g_(int(p.integer("grid"))),
        b_(std::size_t(p.integer("block"))),
        n_(std::size_t(g_) * b_),
        overlap_(p.flag("overlap")),
        write_c_(!p.text("output_csv").empty()),
        a_(matrix(n_, 1)),
        bm_(matrix(n_, 2)),
        c_(std::size_t(g_ * g_)) {
    if (n.processors() < g_ * g_)
      throw SettingError({"workload.grid", kNetworkKey},
                         "a " + std::to_string(g_) + " x " + std::to_string(g_) + " grid needs " +
                             std::to_string(g_ * g_) + " processors; the network has " +
                             std::to_string(n.processors()) +
                             " (e.g. network.family = \"mesh\" with network.workers = " +
                             std::to_string(g_ * g_ - 1) + ")");
    for (int k = 0; k < g_ * g_; ++k) processors_.push_back(n.processor_name(k));
    for (int i = 0; i < g_; ++i)
      for (int j = 0; j < g_; ++j) {
        if (j + 1 < g_) neighbours_ += linked(n, cell(i, j), cell(i, j + 1));
        if (i + 1 < g_) neighbours_ += linked(n, cell(i, j), cell(i + 1, j));
      }
  }

  void build(Builder& b) override {
    b.processes("cell", g_ * g_, [this](Process& p, int k) {
       run(p, k / g_, k % g_);
     }).placed_on(processors_);
    right_.resize(std::size_t(g_ * g_));
    down_.resize(std::size_t(g_ * g_));
    for (int i = 0; i < g_; ++i)
      for (int j = 0; j < g_; ++j) {
        if (j + 1 < g_)
          right_[std::size_t(cell(i, j))].emplace(
              b.channel<Wire>("right" + at(i, j), member(cell(i, j)), member(cell(i, j + 1))));
        if (i + 1 < g_)
          down_[std::size_t(cell(i, j))].emplace(
              b.channel<Wire>("down" + at(i, j), member(cell(i, j)), member(cell(i + 1, j))));
      }
    Values c(b_ * b_, 0);
    const Kernel step = multiply(c, own_a(0, 0), own_b(0, 0));
    for (int k = 0; k < g_ * g_; ++k) b.code(member(k), step);
  }

  void results(Results& r) const override {
    const double tp = end_us_ - start_us_;
    r.set("grid", std::int64_t(g_));
    r.set("block", std::int64_t(b_));
    r.set("n", std::int64_t(n_));
    r.set("overlap", overlap_);
    r.set("precision", std::is_same_v<Value, float> ? "real32" : "real64");
    r.set("tp_us", tp);
    r.set("mflops", 2.0 * double(n_) * double(n_) * double(n_) / tp);
    r.set("block_step_cycles", step_cycles_);
    r.set("block_bytes", std::int64_t(b_ * b_ * sizeof(Value)));
    r.set("channels_on_one_link", std::int64_t(neighbours_));
    r.set("channels", std::int64_t(2 * g_ * (g_ - 1)));
    r.set("max_abs_error", max_error());
    r.set("c_checksum", checksum());
    if (write_c_) r.table("output_csv", column_names(), c_rows());
  }

 private:
  int cell(int i, int j) const { return i * g_ + j; }
  static std::string member(int k) { return "cell[" + std::to_string(k) + "]"; }
  static std::string at(int i, int j) {
    return "[" + std::to_string(i) + "][" + std::to_string(j) + "]";
  }
  static int linked(const Network& n, int from, int to) {
    const auto near = n.neighbours(from);
    return std::find(near.begin(), near.end(), to) != near.end() ? 1 : 0;
  }

  // C := C + a.b, recorded as it computes: the new C and the kernel the cell runs.
  Kernel multiply(Values& c, const Values& a, const Values& b) const {
    return record_kernel<S>("BLOCK.MAC", [&] {
      std::vector<S> cs(c.begin(), c.end()), as(a.begin(), a.end()), bs(b.begin(), b.end());
      declare(cs, "c");
      declare(as, "a");
      declare(bs, "b");
      multiply_add(cs, as, bs, b_);
      for (std::size_t e = 0; e < c.size(); ++e) c[e] = cs[e].value();
    });
  }

  // The edge cells' own blocks (A's k-th block of row i, B's k-th block of column j).
  Values own_a(int i, int k) const {
    const auto f = block(a_, n_, b_, std::size_t(i), std::size_t(k));
    return Values(f.begin(), f.end());
  }
  Values own_b(int k, int j) const {
    const auto f = block(bm_, n_, b_, std::size_t(k), std::size_t(j));
    return Values(f.begin(), f.end());
  }

  void run(Process& p, int i, int j) {
    const int me = cell(i, j);
    if (me == 0) start_us_ = p.now_us();
    const auto next_a = [&](int k) {
      return j == 0 ? own_a(i, k) : p.in(right_[std::size_t(cell(i, j - 1))]->in());
    };
    const auto next_b = [&](int k) {
      return i == 0 ? own_b(k, j) : p.in(down_[std::size_t(cell(i - 1, j))]->in());
    };
    Values c(b_ * b_, 0), a = next_a(0), b = next_b(0);
    for (int k = 0; k < g_; ++k) {
      Values a2, b2;
      const bool more = k + 1 < g_;
      std::vector<Process::Body> branches;
      if (more)
        branches.push_back([&](Process& q) {
          a2 = j == 0 ? own_a(i, k + 1) : q.in(right_[std::size_t(cell(i, j - 1))]->in());
        });
      if (more)
        branches.push_back([&](Process& q) {
          b2 = i == 0 ? own_b(k + 1, j) : q.in(down_[std::size_t(cell(i - 1, j))]->in());
        });
      if (j + 1 < g_)
        branches.push_back([&](Process& q) { q.out(right_[std::size_t(me)]->out(), a); });
      if (i + 1 < g_)
        branches.push_back([&](Process& q) { q.out(down_[std::size_t(me)]->out(), b); });
      const auto mac = [&](Process& q) {
        const Kernel k_step = multiply(c, a, b);
        if (me == 0 && k == 0) step_cycles_ = q.cycles(k_step);
        q.compute(k_step);
      };
      if (overlap_) {
        branches.push_back(mac);
        p.par(branches);
      } else {
        for (const auto& branch : branches) branch(p);
        mac(p);
      }
      a = std::move(a2);
      b = std::move(b2);
    }
    c_[std::size_t(me)] = c;
    end_us_ = std::max(end_us_, p.now_us());
  }

  // Against the product in double precision (Eigen), over the whole C.
  double max_error() const {
    using M = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const M a =
        Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            a_.data(), long(n_), long(n_))
            .template cast<double>();
    const M bm =
        Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            bm_.data(), long(n_), long(n_))
            .template cast<double>();
    const M exact = a * bm;
    double worst = 0;
    for (int i = 0; i < g_; ++i)
      for (int j = 0; j < g_; ++j)
        for (std::size_t r = 0; r < b_; ++r)
          for (std::size_t s = 0; s < b_; ++s)
            worst = std::max(worst, std::abs(double(c_[std::size_t(cell(i, j))][r * b_ + s]) -
                                             exact(long(std::size_t(i) * b_ + r),
                                                   long(std::size_t(j) * b_ + s))));
    return worst;
  }

  // Element (row, col) of the whole C, from the block of the cell that computed it.
  Value c_at(std::size_t row, std::size_t col) const {
    return c_[std::size_t(cell(int(row / b_), int(col / b_)))][(row % b_) * b_ + col % b_];
  }

  // The checksum of C, row-major over the whole matrix (programs/support/checksum.hpp).
  std::string checksum() const {
    std::vector<float> c;  // C row-major over the whole matrix, as REAL32
    for (std::size_t row = 0; row < n_; ++row)
      for (std::size_t col = 0; col < n_; ++col) c.push_back(float(c_at(row, col)));
    return programs::fnv1a_hex(c);
  }

  // C for workload.output_csv: one line per row, columns c1 ... cn.
  std::vector<std::string> column_names() const {
    std::vector<std::string> names;
    for (std::size_t col = 1; col <= n_; ++col) names.push_back("c" + std::to_string(col));
    return names;
  }
  std::vector<std::vector<double>> c_rows() const {
    std::vector<std::vector<double>> rows(n_);
    for (std::size_t row = 0; row < n_; ++row)
      for (std::size_t col = 0; col < n_; ++col) rows[row].push_back(double(c_at(row, col)));
    return rows;
  }

  int g_;
  std::size_t b_, n_;
  bool overlap_;
  bool write_c_;               // workload.output_csv is set
  std::vector<float> a_, bm_;  // A and B, n x n row-major
  std::vector<Values> c_;      // C's blocks, by cell
  std::vector<std::string> processors_;
  std::vector<std::optional<Chan<Wire>>> right_, down_;
  int neighbours_ = 0;
  std::int64_t step_cycles_ = 0;
  double start_us_ = 0, end_us_ = 0;
};

}  // namespace

T800SIM_WORKLOAD(systolic_matmul) {
  return {
      "systolic-matmul",
      "a systolic matrix product on a grid of transputers: blocks of A flow along the rows, blocks "
      "of B down the columns, each cell multiplies while its links move the next blocks",
      {integer_param("grid", 4, "cells per side of the grid (grid x grid processors)", 1, 32),
       integer_param("block", 8, "rows and columns of a block (the matrices are grid*block square)",
                     1, 64),
       flag_param("overlap", true,
                  "communicate in PAR with the multiply (false: one after the other)"),
       precision_param("precision", "real32", "occam REAL32 or REAL64 arithmetic and blocks"),
       output_file_param("output_csv",
                         "C as CSV (one line per row, columns c1 ... cn), relative to the scene; "
                         "empty = none")},
      [](const Params& p, const Network& n) -> std::unique_ptr<Program> {
        if (p.text("precision") == "real64") return std::make_unique<Systolic<Real64>>(p, n);
        return std::make_unique<Systolic<Real32>>(p, n);
      }};
}

}  // namespace systolic
