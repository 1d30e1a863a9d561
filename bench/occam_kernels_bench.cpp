// The code t800sim generates for a dozen small kernels, each the C++ twin of an occam PROC in
// bench/occam/ (a DAXPY, a dot product, a matrix-vector product, an FFT butterfly, a bit-reversal
// permutation, Horner's rule, an integer sum, deep REAL expressions, an elimination row update, a
// clamp with an IF), so its instructions and cycles per call can be set beside what the INMOS
// occam compiler emits for the PROC (docs/compute-model.md, "Against the INMOS compiler"). A
// benchmark, not a test: it prints figures.
//
//   build/bench/occam_kernels_bench                 a row per kernel: instructions and cycles per
//   call build/bench/occam_kernels_bench --listing K01   one kernel's code, run by run
//   build/bench/occam_kernels_bench --unchecked     compiled without run-time checks (oc -u)
//
// Timed by the static model of a T800-20 with everything on chip, from the PROC's entry (its ajw)
// to its ret: the caller's argument set-up and call are not counted, as in the oc figures
// (bench/occam/README.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "t800/compute_model.hpp"
#include "t800sim/kernel.hpp"

namespace {

using t800sim::at;
using t800sim::declare;
using t800sim::declare_variable;
using t800sim::Int;
using t800sim::Real32;
using t800sim::Real64;
using t800sim::seq;

// How occam passes a scalar parameter (D7205A, bench/occam/README.md): a VAL one that fits in a
// word (INT, REAL32) by value, in the callee's workspace; a VAL REAL64, and any result parameter,
// through a pointer -- here a one-element array, declared as the parameters are.
template <class S>
void val_parameter(S& v, const char* name) {
  if constexpr (sizeof(typename S::value_type) > 4)
    declare(&v, 1, name);
  else
    declare_variable(v, name);
}
template <class S>
void result_parameter(S& v, const char* name) {
  declare(&v, 1, name);
}

template <class S = Real64>
std::vector<S> ramp(std::size_t n, double start, double step) {
  std::vector<S> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = S(typename S::value_type(start + step * double(i)));
  return v;
}

// K01 (REAL64) and K03 (REAL32): SEQ i = 0 FOR 100: y[i] := y[i] + (a * x[i])
template <class S>
t800sim::Kernel axpy(const char* name) {
  return t800sim::record_kernel<S>(name, [] {
    std::vector<S> x = ramp<S>(100, 0, 1), y = ramp<S>(100, 1, 0);
    S a = typename S::value_type(2);
    declare(x, "x");
    declare(y, "y");
    val_parameter(a, "a");
    for (std::size_t i : seq<S>(100)) y[i] = y[i] + a * x[i];
  });
}

// K04: s := 0.0; SEQ i = 0 FOR 100: s := s + (x[i] * y[i])
t800sim::Kernel dot() {
  return t800sim::record_kernel<Real64>("K04 dot product", [] {
    std::vector<Real64> x = ramp(100, 0, 0.5), y = ramp(100, 1, 0.25);
    Real64 s = 1.0;
    declare(x, "x");
    declare(y, "y");
    result_parameter(s, "s");
    s = Real64(0.0);
    for (std::size_t i : seq<Real64>(100)) s = s + x[i] * y[i];
  });
}

// K05: SEQ i = 0 FOR 6: r[i] := 0.0; SEQ j = 0 FOR 6: r[i] := r[i] + (m[i][j] * v[j])
// (m flat, its subscript (i * 6) + j computed).
t800sim::Kernel matvec() {
  return t800sim::record_kernel<Real64>("K05 matrix-vector", [] {
    std::vector<Real64> m = ramp(36, 1, 0.5), v = ramp(6, 2, -0.25), r(6, Real64(9.0));
    declare(m, "m");
    declare(v, "v");
    declare(r, "r");
    for (Int i : seq<Real64>(6)) {
      at(r, i) = Real64(0.0);
      for (Int j : seq<Real64>(6)) at(r, i) = at(r, i) + at(m, i * Int(6) + j) * at(v, j);
    }
  });
}

// K06: one FFT stage over [64]REAL64 re, im: nb groups of 2h points, every subscript written out
// as the occam has it (re[(k + ((2*h)*b)) + h]).
t800sim::Kernel butterfly(int h_value, int nb_value) {
  return t800sim::record_kernel<Real64>(
      "K06 butterfly h=" + std::to_string(h_value), [h_value, nb_value] {
        std::vector<Real64> re = ramp(64, 1, 0.125), im = ramp(64, -1, 0.0625);
        Real64 wr = 0.75, wi = -0.5;
        Int h = h_value, nb = nb_value;
        declare(re, "re");
        declare(im, "im");
        val_parameter(wr, "wr");
        val_parameter(wi, "wi");
        val_parameter(h, "h");
        val_parameter(nb, "nb");
        for (Int b : seq<Real64>(std::size_t(nb_value))) {
          for (Int k : seq<Real64>(std::size_t(h_value))) {
            const auto p = [&] { return k + Int(2) * h * b; };
            const auto q = [&] { return k + Int(2) * h * b + h; };
            const Real64 tr = wr * at(re, q()) - wi * at(im, q());
            const Real64 ti = wr * at(im, q()) + wi * at(re, q());
            at(re, q()) = at(re, p()) - tr;
            at(im, q()) = at(im, p()) - ti;
            at(re, p()) = at(re, p()) + tr;
            at(im, p()) = at(im, p()) + ti;
          }
        }
      });
}

// K07: SEQ i = 0 FOR 64: j := rev[i]; IF i < j: swap a[i] and a[j] (rev: 6-bit bit reversal).
t800sim::Kernel bit_reversal() {
  return t800sim::record_kernel<Real64>("K07 bit reversal", [] {
    std::vector<Int> rev(64), a(64);
    for (int i = 0; i < 64; ++i) {
      int r = 0;
      for (int bit = 0; bit < 6; ++bit) r |= ((i >> bit) & 1) << (5 - bit);
      rev[std::size_t(i)] = r;
      a[std::size_t(i)] = 3 * i + 1;
    }
    declare(rev, "rev");
    declare(a, "a");
    for (Int i : seq<Real64>(64)) {
      const Int j = at(rev, i);
      if (i < j) {
        const Int t = at(a, i);
        at(a, i) = at(a, j);
        at(a, j) = t;
      }
    }
  });
}

// K08: p := c[7]; SEQ i = 0 FOR 7: p := (p * x) + c[6 - i]
t800sim::Kernel horner() {
  return t800sim::record_kernel<Real64>("K08 Horner", [] {
    std::vector<Int> c{3, -1, 4, 1, -5, 9, 2, -6};
    Int x = 2, p = 0;
    declare(c, "c");
    val_parameter(x, "x");
    result_parameter(p, "p");
    p = c[7];
    for (Int i : seq<Real64>(7)) p = p * x + at(c, Int(6) - i);
  });
}

// K09: s := 0; SEQ i = 0 FOR 100: s := s + x[i]
t800sim::Kernel integer_sum() {
  return t800sim::record_kernel<Real64>("K09 integer sum", [] {
    std::vector<Int> x(100);
    for (int i = 0; i < 100; ++i) x[std::size_t(i)] = 7 * i - 300;
    Int s = 5;
    declare(x, "x");
    result_parameter(s, "s");
    s = Int(0);
    for (std::size_t i : seq<Real64>(100)) s = s + x[i];
  });
}

// K10: r := ((a*b)+(c*d))*((e*f)-(g*h)); r2 := (that) / (((a+b)*(c-d))+((e+f)*(g-h))) *
// (((a-c)*(b+d))-((e-g)*(f+h)))), each written out again as the occam has it.
t800sim::Kernel deep_expressions() {
  return t800sim::record_kernel<Real64>("K10 deep expressions", [] {
    Real64 a = 1.5, b = 2.25, c = -0.5, d = 3.0, e = 0.75, f = -1.25, g = 2.5, h = 0.125;
    Real64 r = 0, r2 = 0;
    for (Real64* v : {&a, &b, &c, &d, &e, &f, &g, &h}) val_parameter(*v, "v");
    result_parameter(r, "r");
    result_parameter(r2, "r2");
    r = ((a * b) + (c * d)) * ((e * f) - (g * h));
    r2 =
        (((a * b) + (c * d)) * ((e * f) - (g * h))) /
        ((((a + b) * (c - d)) + ((e + f) * (g - h))) * (((a - c) * (b + d)) - ((e - g) * (f + h))));
  });
}

// K11: SEQ j = k FOR 6 - k: row[j] := row[j] - (f * pivot[j]), k a variable (a parameter).
t800sim::Kernel row_update(int k_value) {
  return t800sim::record_kernel<Real64>("K11 row update k=" + std::to_string(k_value), [k_value] {
    std::vector<Real64> pivot = ramp(6, 2, 0.5), row = ramp(6, -1, 0.75);
    Real64 f = 0.375;
    Int k = k_value;
    declare(pivot, "pivot");
    declare(row, "row");
    val_parameter(f, "f");
    val_parameter(k, "k");
    for (std::size_t j : seq<Real64>(k, Int(6) - k)) row[j] = row[j] - f * pivot[j];
  });
}

// K12: SEQ i = 0 FOR 100: IF x[i] < lo: x[i] := lo; x[i] > hi: x[i] := hi; TRUE: SKIP
t800sim::Kernel clamp(double start) {
  return t800sim::record_kernel<Real64>("K12 clamp", [start] {
    std::vector<Real64> x = ramp(100, start, 0.01);
    Real64 lo = -1.0, hi = 2.0;
    declare(x, "x");
    val_parameter(lo, "lo");
    val_parameter(hi, "hi");
    for (std::size_t i : seq<Real64>(100)) {
      if (x[i] < lo)
        x[i] = lo;
      else if (x[i] > hi)
        x[i] = hi;
    }
  });
}

struct Entry {
  const char* id;
  const char* what;
  std::function<t800sim::Kernel()> record;
};

std::vector<Entry> kernels() {
  return {
      {"K01", "DAXPY [100]REAL64", [] { return axpy<Real64>("K01 DAXPY"); }},
      {"K03", "SAXPY [100]REAL32", [] { return axpy<Real32>("K03 SAXPY"); }},
      {"K04", "dot product [100]REAL64", dot},
      {"K05", "6x6 matrix x vector", matvec},
      {"K06a", "FFT butterfly h=16 nb=2", [] { return butterfly(16, 2); }},
      {"K06b", "FFT butterfly h=1 nb=32", [] { return butterfly(1, 32); }},
      {"K07", "bit reversal [64]INT", bit_reversal},
      {"K08", "Horner [8]INT", horner},
      {"K09", "integer sum [100]INT", integer_sum},
      {"K10", "deep REAL64 expressions", deep_expressions},
      {"K11a", "row update k=0", [] { return row_update(0); }},
      {"K11b", "row update k=3", [] { return row_update(3); }},
      {"K12a", "clamp, all in range", [] { return clamp(0.0); }},
      {"K12b", "clamp, all below lo", [] { return clamp(-5.0); }},
  };
}

// The unit without its caller's part: the arguments' addresses and the call, before the PROC's ajw.
t800::codegen::CodeUnit proc_alone(t800::codegen::CodeUnit unit) {
  auto& first = unit.runs.front().code;
  const auto entry = std::find_if(first.begin(), first.end(),
                                  [](const auto& in) { return in.op == t800::isa::Op::ajw; });
  first.erase(first.begin(), entry);
  return unit;
}

void print_listing(const t800::codegen::CodeUnit& unit) {
  for (const auto& run : unit.runs) {
    std::printf("-- %s (x%lld)\n", run.label.c_str(), (long long)run.times);
    for (const auto& in : run.code)
      std::printf("   %-22s %s\n", t800::isa::assembly(in).c_str(), in.note.c_str());
  }
}

int usage(const char* why) {
  std::fprintf(stderr,
               "occam_kernels_bench: %s\nusage: occam_kernels_bench [--unchecked] [--listing ID]\n",
               why);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  bool checked = true;
  std::string listing;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--unchecked") == 0)
      checked = false;
    else if (std::strcmp(argv[i], "--listing") == 0 && i + 1 < argc)
      listing = argv[++i];
    else
      return usage(("unknown argument " + std::string(argv[i])).c_str());
  }
  t800::ComputeSettings settings;
  settings.checked = checked;
  const t800::ComputeModel model(t800::ProcessorConfig{}, settings);
  bool found = listing.empty();
  if (listing.empty())
    std::printf("%-5s %-26s %12s %10s %8s\n", "id", "kernel", "instructions", "cycles", "code B");
  for (const Entry& e : kernels()) {
    if (!listing.empty() && listing != e.id) continue;
    found = true;
    const t800sim::Kernel kernel = e.record();
    if (!listing.empty()) {
      print_listing(model.annotated_code(kernel.work().code));
      continue;
    }
    const t800::codegen::CodeUnit unit = proc_alone(model.code(kernel.work().code));
    std::printf("%-5s %-26s %12lld %10lld %8d\n", e.id, e.what,
                (long long)unit.executed_instructions(), (long long)model.time(unit).cycles,
                unit.code_bytes);
  }
  return found ? 0 : usage(("no kernel " + listing).c_str());
}
