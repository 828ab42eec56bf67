// fluidbed — the bracketed root solve shared by the solvers of settling/ and elastic/.
// Needs Boost.Math (the only header of core/ that does).
#pragma once

#include <boost/math/tools/roots.hpp>
#include <cstdint>

namespace fluidbed::detail {

// A bound on the iterations of every TOMS 748 solve of the library: each converges to
// eps_tolerance<T> in about ten, so the bound only stops a solve that would not end.
inline constexpr std::uintmax_t root_iteration_limit = 200;

// The root of f in [a, b], f(a) = f_a and f(b) = f_b of opposite signs, by TOMS 748 (Alefeld,
// Potra & Shi 1995, Boost.Math's toms748_solve) to the precision of T: the middle of the final
// bracket.
template <class T, class F>
T bracketed_root(const F& f, const T& a, const T& b, const T& f_a, const T& f_b) {
  std::uintmax_t iterations = root_iteration_limit;
  const auto bracket =
      boost::math::tools::toms748_solve(f, a, b, f_a, f_b, boost::math::tools::eps_tolerance<T>(), iterations);
  return (bracket.first + bracket.second) / T(2);
}

}  // namespace fluidbed::detail
