#include "t800/repeated_sum.hpp"

#include <algorithm>
#include <cmath>

namespace t800 {

namespace {

// Below this many additions the loop itself is cheaper than the binade arithmetic (frexp, ldexp, a
// division): most messages are tens of bytes, each adding its packets' durations here.
constexpr std::int64_t kShortRun = 64;

// The binade of x > 0: 2^e <= x < 2^(e+1).
int binade(double x) {
  int e = 0;
  std::frexp(x, &e);
  return e;
}

}  // namespace

// Within one binade [2^e, 2^(e+1)) the doubles are the multiples of u = ulp, so adding `term` to a
// sum there adds term rounded to a multiple of u: a constant step delta, except that a term exactly
// halfway between two multiples rounds to an even result. After one such rounding the sum is even
// and every later step is the same even multiple of u, so the step measured between the second and
// third additions in a binade holds for the rest of it. The steps are taken in bulk while they stay
// safely inside the binade (a sum x + delta <= 2^(e+1) - 2u cannot round out of it); the additions
// that cross into the next binade are done one by one.
double add_repeatedly(double sum, double term, std::int64_t times) {
  while (times > 0) {
    if (times < kShortRun) {  // what is left, as the loop it stands for
      for (; times > 0; --times) sum += term;
      return sum;
    }
    if (sum <= 0 || !std::isnormal(sum) || !(term > 0)) {
      sum += term;
      --times;
      continue;
    }
    const double first = sum + term, second = first + term, third = second + term;
    times -= 3;
    sum = third;
    if (!std::isnormal(first) || binade(first) != binade(third)) continue;
    const double delta = third - second;  // exact: both in one binade
    if (delta == 0) return sum;           // the term is lost in the sum from now on
    const int e = binade(third);          // third lies in [2^(e-1), 2^e)
    const double ulp = std::ldexp(1.0, e - 53);
    const double top = std::ldexp(1.0, e) - 2 * ulp;
    if (third + delta > top) continue;
    double steps = std::floor((top - third) / delta);
    while (steps > 0 && third + steps * delta > top) --steps;  // the division may round up
    while (third + (steps + 1) * delta <= top) ++steps;
    const std::int64_t bulk = std::min<std::int64_t>(times, std::int64_t(steps));
    sum = third + double(bulk) * delta;
    times -= bulk;
  }
  return sum;
}

}  // namespace t800
