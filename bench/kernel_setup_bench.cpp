// Set-up cost of recorded kernels (issue 25, item 5): what a kernel costs before its simulation
// starts -- recording it, compiling the recording to T800 code, and timing that code with the
// static model -- for programs written as a user would write them with the SDK: LINPACK 100 (dgefa
// and dgesl, 5,148 DAXPY calls) and a 1,024-point radix-2 FFT. A benchmark, not a test: it prints
// figures. Each kernel is measured in a child process of its own, so its peak memory is its own.
//
//   build/bench/kernel_setup_bench            every kernel
//   build/bench/kernel_setup_bench linpack    one (linpack, fft)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "t800/compute_model.hpp"
#include "t800sim/kernel.hpp"

namespace {

using t800sim::Real64;
using t800sim::seq;

// LINPACK's BLAS as its Fortran has them (unit strides), on pointers into the declared arrays.
void daxpy(std::size_t n, Real64 da, const Real64* dx, Real64* dy) {
  for (std::size_t i : seq<Real64>(n)) dy[i] = dy[i] + da * dx[i];
}

void dscal(std::size_t n, Real64 da, Real64* dx) {
  for (std::size_t i : seq<Real64>(n)) dx[i] = da * dx[i];
}

std::size_t idamax(std::size_t n, const Real64* dx) {
  std::size_t largest = 0;
  Real64 dmax = fabs(dx[0]);
  for (std::size_t i : seq<Real64>(n)) {
    if (fabs(dx[i]) > dmax) {
      t800sim::integer<Real64>(t800sim::IntegerStatement::move);  // largest := i
      largest = i;
      dmax = fabs(dx[i]);
    }
  }
  return largest;
}

// LU factorisation with partial pivoting of the column-major n x n matrix a, then the solution of
// a x = b in b (LINPACK's dgefa and dgesl, without its singularity test).
void linpack(std::size_t n, std::vector<Real64>& a, std::vector<Real64>& b) {
  std::vector<std::size_t> pivot(n);
  const auto column = [&](std::size_t k) { return a.data() + k * n; };
  for (std::size_t k = 0; k + 1 < n; ++k) {
    Real64* ck = column(k);
    const std::size_t l = idamax(n - k, ck + k) + k;
    pivot[k] = l;
    if (l != k) std::swap(ck[l], ck[k]);
    const Real64 t = Real64(-1.0) / ck[k];
    dscal(n - k - 1, t, ck + k + 1);
    for (std::size_t j = k + 1; j < n; ++j) {
      Real64* cj = column(j);
      const Real64 s = cj[l];
      if (l != k) std::swap(cj[l], cj[k]);
      daxpy(n - k - 1, s, ck + k + 1, cj + k + 1);
    }
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const std::size_t l = pivot[k];
    const Real64 t = b[l];
    if (l != k) std::swap(b[l], b[k]);
    daxpy(n - k - 1, t, column(k) + k + 1, b.data() + k + 1);
  }
  for (std::size_t k = n; k-- > 0;) {
    b[k] = b[k] / column(k)[k];
    daxpy(k, -b[k], column(k), b.data());
  }
}

// LINPACK's matrix generator (matgen): a pseudo-random matrix, b its rows' sums.
void matgen(std::size_t n, std::vector<Real64>& a, std::vector<Real64>& b) {
  int seed = 1325;
  for (Real64& x : a) {
    seed = 3125 * seed % 65536;
    x = Real64((seed - 32768.0) / 16384.0);
  }
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0;
    for (std::size_t j = 0; j < n; ++j) sum += a[j * n + i].value();
    b[i] = Real64(sum);
  }
}

t800sim::Kernel record_linpack() {
  constexpr std::size_t n = 100;
  return t800sim::record_kernel<Real64>("LINPACK", [] {
    std::vector<Real64> a(n * n), b(n);
    matgen(n, a, b);
    t800sim::declare(a, "a");
    t800sim::declare(b, "b");
    linpack(n, a, b);
    // b was A's row sums, so the solution is all ones: a kernel recorded wrongly would show here.
    for (const Real64& x : b)
      if (std::fabs(x.value() - 1.0) > 1e-9) throw std::runtime_error("LINPACK: x is not 1");
  });
}

// An in-place radix-2 decimation-in-time FFT of 1,024 points, written with x[i] subscripts: the
// bit-reversal permutation, then log2 n stages of butterflies with the twiddles precomputed.
t800sim::Kernel record_fft() {
  constexpr std::size_t n = 1024;
  return t800sim::record_kernel<Real64>("FFT", [] {
    std::vector<Real64> re(n), im(n), wr(n / 2), wi(n / 2);
    for (std::size_t i = 0; i < n; ++i) re[i] = Real64(std::sin(0.1 * double(i)));
    for (std::size_t k = 0; k < n / 2; ++k) {
      wr[k] = Real64(std::cos(2 * M_PI * double(k) / n));
      wi[k] = Real64(-std::sin(2 * M_PI * double(k) / n));
    }
    for (auto* v : {&re, &im, &wr, &wi}) t800sim::declare(*v, "x");
    for (std::size_t i = 0, j = 0; i < n; ++i) {
      if (i < j) {
        std::swap(re[i], re[j]);
        std::swap(im[i], im[j]);
      }
      std::size_t bit = n >> 1;
      for (; j & bit; bit >>= 1) j ^= bit;
      j |= bit;
    }
    for (std::size_t h = 1; h < n; h *= 2) {
      const std::size_t stride = n / (2 * h);
      for (std::size_t b : seq<Real64>(n / (2 * h))) {
        for (std::size_t k : seq<Real64>(h)) {
          const std::size_t p = 2 * h * b + k, q = p + h;
          const Real64 tr = wr[k * stride] * re[q] - wi[k * stride] * im[q];
          const Real64 ti = wr[k * stride] * im[q] + wi[k * stride] * re[q];
          re[q] = re[p] - tr;
          im[q] = im[p] - ti;
          re[p] = re[p] + tr;
          im[p] = im[p] + ti;
        }
      }
    }
  });
}

struct Measured {
  double record_s = 0, compile_s = 0, time_s = 0;
  long peak_kib = 0;
  std::int64_t events = 0, runs = 0, instructions = 0, cycles = 0;
  int code_bytes = 0;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Measured measure(const std::function<t800sim::Kernel()>& record) {
  Measured m;
  auto start = std::chrono::steady_clock::now();
  const t800sim::Kernel kernel = record();
  m.record_s = seconds_since(start);
  const t800::ComputeModel model(t800::ProcessorConfig{}, t800::ComputeSettings{});
  start = std::chrono::steady_clock::now();
  const t800::codegen::CodeUnit& unit = model.code(kernel.work().code);
  m.compile_s = seconds_since(start);
  start = std::chrono::steady_clock::now();
  m.cycles = model.time(unit).cycles;
  m.time_s = seconds_since(start);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  m.peak_kib = usage.ru_maxrss;
  m.events = std::int64_t(kernel.work().code->events().size());
  m.runs = std::int64_t(unit.runs.size());
  m.instructions = unit.executed_instructions();
  m.code_bytes = unit.code_bytes;
  return m;
}

// In a child process, so each kernel's peak memory is its own; the figures come back on a pipe.
bool measure_in_child(const std::function<t800sim::Kernel()>& record, Measured& out) {
  int fds[2];
  if (pipe(fds) != 0) return false;
  const pid_t child = fork();
  if (child == 0) {
    close(fds[0]);
    const Measured m = measure(record);
    const bool written = write(fds[1], &m, sizeof m) == ssize_t(sizeof m);
    _exit(written ? 0 : 1);
  }
  close(fds[1]);
  const bool read_all = child > 0 && read(fds[0], &out, sizeof out) == ssize_t(sizeof out);
  close(fds[0]);
  int status = 0;
  if (child > 0) waitpid(child, &status, 0);
  return read_all && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::pair<std::string, std::function<t800sim::Kernel()>>> kernels{
      {"linpack", record_linpack}, {"fft", record_fft}};
  const std::string only = argc > 1 ? argv[1] : "";
  const bool known = only.empty() || std::any_of(kernels.begin(), kernels.end(),
                                                 [&](const auto& k) { return k.first == only; });
  if (!known || argc > 2) {
    std::fprintf(stderr, "usage: kernel_setup_bench [linpack|fft] (not \"%s\")\n", only.c_str());
    return 2;
  }
  std::printf("%-8s %10s %9s %9s %9s %9s %9s %12s %10s %13s\n", "kernel", "events", "record s",
              "compile s", "time s", "peak MiB", "runs", "instructions", "code B", "cycles");
  int failures = 0;
  for (const auto& [name, record] : kernels) {
    if (!only.empty() && name != only) continue;
    Measured m;
    if (!measure_in_child(record, m)) {
      std::fprintf(stderr, "kernel_setup_bench: %s failed\n", name.c_str());
      ++failures;
      continue;
    }
    std::printf("%-8s %10lld %9.3f %9.3f %9.3f %9.1f %9lld %12lld %10d %13lld\n", name.c_str(),
                (long long)m.events, m.record_s, m.compile_s, m.time_s, m.peak_kib / 1024.0,
                (long long)m.runs, (long long)m.instructions, m.code_bytes, (long long)m.cycles);
  }
  return failures ? 1 : 0;
}
