// fluidbed — Di Felice (1994) drag with a Reynolds-dependent voidage exponent.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/constants.hpp"
#include "../single_particle/drag_coefficient.hpp"
#include "drag_law.hpp"

namespace fluidbed::drag {

// Di Felice, R. (1994), "The voidage function for fluid-particle interaction systems",
// Int. J. Multiphase Flow 20, 153–159, doi:10.1016/0301-9322(94)90011-6:
//
//   β_pressure_gradient = ¾ C_D(Re) ρ_f w (1 − ε) / d · ε^(2 − χ(Re)),
//   χ(Re) = 3.7 − 0.65 exp[−½ (1.5 − log10 Re)²],        Re = ρ_f ε w d / μ_f.
//
// Native convention: pressure_gradient (Di Felice's). In the classical convention the
// exponent is −α_d with α_d = χ − 1 = 2.7 − 0.65 exp[…] (seed 000 eq. 3.48). The minimum of
// χ is exactly 3.05 at Re = 10^1.5 (α_d = 2.05; the thesis reads "about 2.1 at roughly
// 28" from a plot); χ → 3.7 in both Reynolds limits and χ(0) = 3.7.
//
// C_D is selectable. Di Felice used Dallavalle's (0.63 + 4.8/√Re)², which is the default
// and what CFDEM, Lethe and waLBerla intend; MFiX's DIFELICE uses Schiller–Naumann, and
// seed 000 (Fig. 3.3) plugs α_d into the Schiller–Naumann eq. 3.34. The two differ by
// ~10 % at Re ≈ 10.
// Validity: Di Felice's data, 0.4 ≲ ε < 1 and 10⁻² < Re < 10⁴.
template <class Coefficient = single_particle::DallavalleCoefficient>
struct DiFelice : DragLaw<DiFelice<Coefficient>> {
  static constexpr Buoyancy native_buoyancy = Buoyancy::pressure_gradient;

  constexpr std::string_view name() const {
    if constexpr (std::is_same_v<Coefficient, single_particle::DallavalleCoefficient>)
      return "DiFeliceDallavalle";
    else return "DiFeliceSchillerNaumann";
  }
  constexpr std::string_view reference() const {
    return "Di Felice, R. (1994) Int. J. Multiphase Flow 20, 153-159, doi:10.1016/0301-9322(94)90011-6";
  }
  constexpr ValidityRange validity() const { return {0.4, 1.0, 1.0e-2, 1.0e4}; }

  // χ(Re); the Re → 0 limit 3.7 is returned at Re = 0.
  template <class S>
  FLUIDBED_HOST_DEVICE static S exponent(const S& re) {
    using std::exp;
    using std::log;
    using T = value_type_of<S>;
    if (!(re > S(0))) return S(FLUIDBED_DECIMAL(T, 3.7));
    const S x = T(1.5) - log(re) / numbers::ln10<T>();
    return FLUIDBED_DECIMAL(T, 3.7) - FLUIDBED_DECIMAL(T, 0.65) * exp(T(-0.5) * x * x);
  }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                     const T& diameter) const {
    using std::pow;
    const S re = particle_reynolds(fluid, diameter, voidage, slip);
    return single_particle::unhindered_beta(Coefficient::cd_times_re(re), voidage, fluid.viscosity, diameter) *
           pow(voidage, 2 - exponent(re));
  }
};

}  // namespace fluidbed::drag
