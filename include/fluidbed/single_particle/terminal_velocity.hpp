// fluidbed — terminal settling velocity of a single sphere in an unbounded fluid: every form,
// and their registry. The closed forms (Stokes, Newton, Dallavalle) and the conventions are in
// terminal_velocity_closed_forms.hpp; this header adds Schiller–Naumann, whose balance is
// solved with Boost.Math.
#pragma once

#include <string_view>

#include "../core/registry.hpp"
#include "../core/root_finding.hpp"
#include "drag_coefficient.hpp"
#include "haider_levenspiel.hpp"
#include "terminal_velocity_closed_forms.hpp"

namespace fluidbed::single_particle {

// Schiller, L., Naumann, A. (1933), Z. Ver. Dtsch. Ing. 77, 318; seed 000 eq. 3.35, with
// the 0.44 branch for Re >= 1000 (SchillerNaumannCoefficient). ¾ C_D Re_t² = Ar is
// solved with Boost.Math toms748 on the bracket [0, Ar/18] (C_D Re >= 24 gives
// Re_t <= Ar/18).
// The law jumps at Re = 1000 (¾ C_D Re² goes from 328 716 to 330 000), so for
// 328 716 < Ar < 330 000 the balance has no root: the drag is below the weight just under
// Re = 1000 and above it at Re = 1000. There the solver converges to the sign change and
// Re_t = 1000 (to rounding) is returned, which keeps Re_t(Ar) continuous and
// non-decreasing.
// dRe_t/dAr follows from the implicit function theorem on the balance,
// 1/(¾ d(C_D Re · Re)/dRe) at Re_t (1/18 at Ar = 0); in the gap above it is that of the
// branch Re_t = 1000 sits on, where the true slope of the flat Re_t(Ar) is 0.
// Validity: Re_t up to about 2·10⁵. Host only: the solve is Boost.Math's TOMS 748, which has
// no device code (the closed forms of this family run on a GPU).
struct SchillerNaumannTerminalVelocity : ArchimedesCorrelation<SchillerNaumannTerminalVelocity> {
  constexpr std::string_view name() const { return "SchillerNaumannTerminalVelocity"; }
  constexpr std::string_view reference() const {
    return "Schiller, L., Naumann, A. (1933) Z. Ver. Dtsch. Ing. 77, 318-320";
  }
  constexpr Validity<1> validity() const { return {{{"terminal_reynolds", 0.0, 2.0e5}}}; }

  template <class T>
  T reynolds_of_archimedes(const T& archimedes) const {
    if (archimedes == T(0)) return T(0);
    const auto balance = [&](const T& re) {
      return T(0.75) * SchillerNaumannCoefficient::cd_times_re(re) * re / archimedes - 1;
    };
    const T hi = archimedes / 18;
    return fluidbed::detail::bracketed_root(balance, T(0), hi, T(-1), balance(hi));
  }

  template <class T>
  ReynoldsWithDerivative<T> reynolds_with_derivative(const T& archimedes) const {
    const T re = reynolds_of_archimedes(archimedes);
    if (re == T(0)) return {re, T(1) / 18};  // the Stokes limit, where (C_D Re)' = ∞ meets Re = 0
    // ¾ (C_D Re)(Re) · Re = Ar, differentiated in Re.
    const Dual<T, 1> force =
        SchillerNaumannCoefficient::cd_times_re(Dual<T, 1>::variable(re, 0)) * Dual<T, 1>::variable(re, 0);
    return {re, T(1) / (T(0.75) * force.derivative[0])};
  }
};

struct TerminalVelocityFamily {
  static constexpr std::string_view what = "terminal velocity";
  static constexpr std::string_view convention =
      "The terminal Reynolds number Re_t = ρ_f u_t d/μ_f of one sphere settling in an unbounded fluid, as a "
      "function of Ar = ρ_f (ρ_p − ρ_f) g d³/μ_f² (the balance ¾ C_D(Re_t) Re_t² = Ar), and its terminal "
      "velocity u_t = Re_t μ_f/(ρ_f d) [m s⁻¹]; heavier-than-fluid particles only (ρ_p > ρ_f).";
};

// The terminal-velocity forms; extend with `TerminalVelocities::with<MyForm>`.
using TerminalVelocities = Registry<TerminalVelocityFamily, StokesTerminalVelocity, NewtonTerminalVelocity,
                                    DallavalleTerminalVelocity, SchillerNaumannTerminalVelocity,
                                    HaiderLevenspielTerminalVelocity>;

}  // namespace fluidbed::single_particle
