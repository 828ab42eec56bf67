// fluidbed — drag coefficient of a single sphere, C_D(Re).
//
// Each law is returned as the product C_D·Re, which is finite at Re = 0 (C_D itself
// diverges there); the suspension laws build β from C_D·Re so that zero slip is never
// 0·∞. Re is the particle Reynolds number of the caller's law: for a suspension law it
// is Re = ρ_f ε w d / μ_f (seed 000 eq. 3.33), for a free particle ρ_f u d / μ_f.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/config.hpp"
#include "../core/dual.hpp"

namespace fluidbed::drag {

// Stokes (1851): C_D = 24/Re. Valid for Re << 1.
struct StokesCoefficient {
  static constexpr std::string_view name = "Stokes";
  static constexpr double reynolds_max = 0.1;
  template <class S>
  FLUIDBED_HOST_DEVICE static constexpr S cd_times_re(const S& /*re*/) {
    return S(24);
  }
};

// Schiller & Naumann (1933), Z. Ver. Dtsch. Ing. 77, 318; as printed in seed 000
// eq. 3.35: C_D = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, C_D = 0.44 for Re >= 1000.
// The law jumps by 0.4 % at Re = 1000 (0.438288 → 0.44); kept as published.
struct SchillerNaumannCoefficient {
  static constexpr std::string_view name = "SchillerNaumann";
  static constexpr double newton_switch_reynolds = 1000.0;
  template <class S>
  FLUIDBED_HOST_DEVICE static S cd_times_re(const S& re) {
    using std::pow;
    using T = value_type_of<S>;
    if (re < constant_as<S>(newton_switch_reynolds)) return 24 * (1 + T(0.15L) * pow(re, T(0.687L)));
    return T(0.44L) * re;
  }
};

// Dallavalle (1948), Micromeritics, Pitman; seed 000 eqs. 3.51 and 3.55:
// C_D = (0.63 + 4.8 Re^-1/2)², i.e. C_D·Re = (0.63 √Re + 4.8)². Smooth for all Re;
// C_D·Re → 23.04 as Re → 0 and C_D → 0.3969 as Re → ∞.
struct DallavalleCoefficient {
  static constexpr std::string_view name = "Dallavalle";
  template <class S>
  FLUIDBED_HOST_DEVICE static S cd_times_re(const S& re) {
    using std::sqrt;
    using T = value_type_of<S>;
    const S root = T(0.63L) * sqrt(re) + T(4.8L);
    return root * root;
  }
};

// C_D = (C_D·Re)/Re for Re > 0.
template <class Coefficient, class S>
FLUIDBED_HOST_DEVICE S drag_coefficient(const S& re) {
  FLUIDBED_EXPECTS(re > S(0));
  return Coefficient::cd_times_re(re) / re;
}

namespace detail {

// ¾ C_D ρ_f w φ / d written as ¾ (C_D·Re) μ_f φ / (ε d²), with Re = ρ_f ε w d / μ_f.
// This is β_classical of a dilute suspension without hindrance (the "ε^0" part shared by
// the Wen–Yu, Di Felice and Mazzei–Lettieri families, seed 000 eq. 3.34).
template <class S, class T>
FLUIDBED_HOST_DEVICE constexpr S single_particle_beta(const S& cd_times_re, const S& voidage, const T& viscosity,
                                                      const T& diameter) {
  return T(0.75) * viscosity / (diameter * diameter) * cd_times_re * (1 - voidage) / voidage;
}

}  // namespace detail
}  // namespace fluidbed::drag
