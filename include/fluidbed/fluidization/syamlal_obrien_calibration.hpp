// fluidbed — the Syamlal–O'Brien drag (drag/syamlal_obrien.hpp) calibrated from a measured
// minimum fluidization state.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/domain.hpp"
#include "../core/errors.hpp"
#include "../drag/syamlal_obrien.hpp"
#include "../properties.hpp"
#include "../single_particle/settling_system.hpp"
#include "../single_particle/terminal_velocity_closed_forms.hpp"

namespace fluidbed::fluidization {

// The Syamlal–O'Brien law (c1, d1) that puts minimum fluidization at the measured superficial
// velocity u_mf and voidage ε_mf: the procedure the MFiX documentation describes, derived here
// from the law's own force balance. At incipient fluidization in the −φ∇p convention
// β w = φ ε (ρ_p − ρ_f) g with w = u_mf/ε_mf, i.e. ¾ C_D(Re_t) Re_t² = Ar, Re_t = Re_s/V_r:
//   1. Ar = ρ_f (ρ_p − ρ_f) g d³/μ_f²;
//   2. Re_t from Ar by Dallavalle's closed form (single_particle::DallavalleTerminalVelocity);
//   3. V_r = Re_s,mf / Re_t,  Re_s,mf = ρ_f (u_mf/ε_mf) d/μ_f;
//   4. B = [V_r (1 + 0.06 Re_t) − A]/(0.06 Re_t),  A = ε_mf^4.14;
//   5. ε_mf ≤ 0.85: c1 = B/ε_mf^1.28, d1 = 1.28 + ln c1/ln 0.85 (continuity at 0.85);
//      ε_mf > 0.85: d1 = ln B/ln ε_mf, c1 = 0.85^(d1 − 1.28).
// The law then reproduces u_mf exactly at ε_mf. A calibration, not a per-cell call: it always
// checks. Throws std::domain_error for arguments out of their domain (u_mf > 0, ε_mf ∈ (0, 1),
// the settling system's), when Ar is beyond the floating-point range, when u_mf is so small that B ≤ 0 (V_r ≤ A/(1 + 0.06 Re_t)), and when
// the data imply c1 or d1 beyond the floating-point range.
template <class T>
drag::SyamlalOBrien syamlal_obrien_from_minimum_fluidization(const T& velocity, const T& voidage, const Fluid<T>& fluid,
                                                             const Particles<T>& particles,
                                                             const T& gravity = standard_gravity_as<T>()) {
  using drag::SyamlalOBrien;
  using std::log;
  using std::pow;
  constexpr std::string_view function = "syamlal_obrien_from_minimum_fluidization";
  require_within(function,
                 join(arguments(Argument<T>{"minimum_fluidization_velocity", velocity, domains::positive<T>()},
                                Argument<T>{"minimum_fluidization_voidage", voidage, domains::open(T(0), T(1))}),
                      single_particle::settling_domain(fluid, particles, gravity)));
  const T archimedes_number = archimedes(fluid, particles, gravity);
  // Valid data can give an Ar beyond the range (a large d³ or ρ_f Δρ g/μ_f²): a status, not an
  // input to Dallavalle's Re_t, whose domain is finite Ar.
  require_finite_result(function, "archimedes", archimedes_number,
                        [&] { return describe(single_particle::settling_domain(fluid, particles, gravity)); });
  const T re_terminal = single_particle::DallavalleTerminalVelocity{}.reynolds(archimedes_number);
  const T ratio = fluid.density * (velocity / voidage) * particles.diameter / fluid.viscosity / re_terminal;
  const T b = (ratio * (1 + FLUIDBED_DECIMAL(T, 0.06) * re_terminal) - pow(voidage, FLUIDBED_DECIMAL(T, 4.14))) /
              (FLUIDBED_DECIMAL(T, 0.06) * re_terminal);
  if (!(b > T(0)))
    fluidbed::detail::throw_domain_error(function, "minimum_fluidization_velocity", velocity,
                                         "too small for this law: it implies B <= 0");
  const T switch_voidage = SyamlalOBrien::switch_voidage<T>();
  const SyamlalOBrien law = [&] {
    if (voidage <= switch_voidage) {
      const T c1 = b / pow(voidage, FLUIDBED_DECIMAL(T, 1.28));
      return SyamlalOBrien(static_cast<double>(c1),
                           static_cast<double>(FLUIDBED_DECIMAL(T, 1.28) + log(c1) / log(switch_voidage)));
    }
    return SyamlalOBrien::continuous_at_switch(static_cast<double>(log(b) / log(voidage)));
  }();
  // Valid data can still imply parameters beyond the range (ε_mf → 1: d1 = ln B/ln ε_mf with
  // ln ε_mf → 0; a subnormal g), with which β would be 0, ∞ or NaN (found by fuzz/).
  if (!(std::isfinite(law.c1()) && law.c1() > 0 && std::isfinite(law.d1())))
    fluidbed::detail::throw_domain_error(function, "minimum_fluidization_voidage", voidage,
                                         "with these data it implies c1 or d1 beyond the floating-point range");
  return law;
}

}  // namespace fluidbed::fluidization
