// fluidbed — terminal settling velocity of a single sphere in an unbounded fluid: the closed
// forms (Stokes, Newton, Dallavalle), which need nothing beyond the standard library. The
// Schiller–Naumann form is solved numerically (Boost.Math) and lives in terminal_velocity.hpp,
// which includes this header and holds the registry TerminalVelocities; include that one
// unless Boost must be avoided (the drag laws and the elastic modulus do).
//
// The force balance ¾ C_D(Re_t) ρ_f u_t²/d = (ρ_p − ρ_f) g, multiplied by ρ_f d³/μ_f², is
//
//   ¾ C_D(Re_t) Re_t² = Ar,    Re_t = ρ_f u_t d / μ_f,   Ar = ρ_f (ρ_p − ρ_f) g d³ / μ_f²,
//
// so each form is a function Re_t(Ar) and u_t = Re_t μ_f/(ρ_f d). Each is a value type with
// the calling shape of settling_system.hpp: law.reynolds(Ar) = Re_t, law(fluid, particles, g)
// = u_t, law.with_derivatives(Ar) (dRe_t/dAr), law.checked(...). The forms differ in the
// single-sphere C_D they assume:
//   Stokes            C_D = 24/Re                   Re_t = Ar/18           (seed 000 eq. 3.37)
//   Newton            C_D = 0.44                    Re_t = √(Ar/0.33)      (seed 000 eq. 3.41)
//   Dallavalle        C_D = (0.63 + 4.8/√Re)²       closed form below     (seed 000 eq. 3.51)
//   Schiller–Naumann  C_D = 24/Re (1 + 0.15 Re^0.687), 0.44 for Re >= 1000  (eq. 3.35; solved in terminal_velocity.hpp)
// Seed 000 uses Dallavalle's u_t for Richardson–Zaki and for its Tables 4.4 and 4.6 (no other
// u_t reproduces them); Stokes and Newton are the Schiller–Naumann limits its exponent
// derivations use.
#pragma once

#include <cmath>
#include <string_view>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/dual.hpp"
#include "settling_system.hpp"

namespace fluidbed::single_particle {

// Stokes (1851), Trans. Camb. Philos. Soc. 9, 8: Re_t = Ar/18, u_t = (ρ_p − ρ_f) g d²/(18 μ_f)
// (seed 000 eq. 3.37). Valid for Re_t <~ 0.1.
struct StokesTerminalVelocity : ArchimedesCorrelation<StokesTerminalVelocity> {
  constexpr std::string_view name() const { return "StokesTerminalVelocity"; }
  constexpr std::string_view reference() const { return "Stokes, G.G. (1851) Trans. Camb. Philos. Soc. 9, 8-106"; }
  constexpr Validity<1> validity() const { return {{{"terminal_reynolds", 0.0, 0.1}}}; }

  template <class S>
  FLUIDBED_HOST_DEVICE constexpr S reynolds_of_archimedes(const S& archimedes) const {
    return archimedes / 18;
  }
};

// Newton regime, C_D = 0.44 (the inertial branch of Schiller–Naumann; seed 000 eq. 3.41
// from Gibilaro (2001), Fluidization-Dynamics, Butterworth-Heinemann): Re_t = √(Ar/0.33),
// i.e. u_t = √(3.0303 g d (ρ_p − ρ_f)/ρ_f). The seed prints 3.03 for 4/(3·0.44) = 3.0303;
// the exact constant is used so that the Schiller–Naumann u_t tends to this one.
// Valid for 1000 <~ Re_t <~ 2·10⁵. dRe_t/dAr is +∞ at Ar = 0.
struct NewtonTerminalVelocity : ArchimedesCorrelation<NewtonTerminalVelocity> {
  constexpr std::string_view name() const { return "NewtonTerminalVelocity"; }
  constexpr std::string_view reference() const {
    return "Gibilaro, L.G. (2001) Fluidization-Dynamics, Butterworth-Heinemann, Oxford (seed 000 eq. 3.41)";
  }
  constexpr Validity<1> validity() const { return {{{"terminal_reynolds", 1.0e3, 2.0e5}}}; }

  template <class S>
  FLUIDBED_HOST_DEVICE S reynolds_of_archimedes(const S& archimedes) const {
    using std::sqrt;
    using T = value_type_of<S>;
    return sqrt(archimedes / (T(0.75) * FLUIDBED_DECIMAL(T, 0.44)));
  }
};

// Dallavalle, J.M. (1948), Micromeritics, 2nd ed., Pitman; seed 000 eq. 3.51:
// C_D = (0.63 + 4.8 Re^−½)², so ¾ C_D Re_t² = ¾ (0.63 Re_t + 4.8 √Re_t)² = Ar is a quadratic
// in √Re_t:
//
//   √Re_t = [−4.8 + √(4.8² + 4·0.63·s)] / (2·0.63) = 2 s / (4.8 + √(4.8² + 2.52 s)),  s = √(4Ar/3),
//
// evaluated in the second (cancellation-free) form. Limits: Re_t → Ar/17.28
// (C_D Re → 23.04, not Stokes's 24) and Re_t → √(4Ar/(3·0.3969)) (C_D → 0.3969, not 0.44).
// Smooth over all Ar >= 0; dRe_t/dAr = 1/17.28 at Ar = 0 (taken as that limit, where the
// closed form's √ would give 0·∞). Validity: Dallavalle's C_D, Re_t up to about 10⁴.
struct DallavalleTerminalVelocity : ArchimedesCorrelation<DallavalleTerminalVelocity> {
  constexpr std::string_view name() const { return "DallavalleTerminalVelocity"; }
  constexpr std::string_view reference() const {
    return "Dallavalle, J.M. (1948) Micromeritics, 2nd ed., Pitman, New York (seed 000 eq. 3.51)";
  }
  constexpr Validity<1> validity() const { return {{{"terminal_reynolds", 0.0, 1.0e4}}}; }

  template <class S>
  FLUIDBED_HOST_DEVICE S reynolds_of_archimedes(const S& archimedes) const {
    using std::sqrt;
    using T = value_type_of<S>;
    if constexpr (is_dual<S>::value)
      if (archimedes == T(0)) return archimedes / FLUIDBED_DECIMAL(T, 17.28);
    const S s = sqrt(4 * archimedes / 3);
    const S root = 2 * s /
                   (FLUIDBED_DECIMAL(T, 4.8) +
                    sqrt(FLUIDBED_DECIMAL(T, 4.8) * FLUIDBED_DECIMAL(T, 4.8) + FLUIDBED_DECIMAL(T, 2.52) * s));
    return root * root;
  }
};

}  // namespace fluidbed::single_particle
