// fluidbed — the Haider–Levenspiel explicit terminal velocity of a sphere or an isometric
// particle.
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "settling_system.hpp"

namespace fluidbed::single_particle {

// Haider, A., Levenspiel, O. (1989), "Drag coefficient and terminal velocity of spherical and
// nonspherical particles", Powder Technol. 58, 63–70, doi:10.1016/0032-5910(89)80008-7; also
// Kunii & Levenspiel (1991), Fluidization Engineering, 2nd ed., ch. 3, eq. 33. With the
// dimensionless diameter and velocity
//
//   d* = d [ρ_f (ρ_p − ρ_f) g/μ_f²]^(1/3) = Ar^(1/3),   u* = u_t [ρ_f²/(μ_f (ρ_p − ρ_f) g)]^(1/3),
//
// their explicit fit is u* = [18/d*² + (2.3348 − 1.7439 φ_s)/√d*]⁻¹, and since Re_t = u* d*,
//
//   Re_t = Ar / (18 + c √Ar),   c = 2.3348 − 1.7439 φ_s   (c = 0.5909 for a sphere),
//
// with Re_t = ρ_f u_t d/μ_f, Ar = ρ_f (ρ_p − ρ_f) g d³/μ_f², d the diameter of the sphere of
// equal volume and φ_s the sphericity. Limits: Re_t → Ar/18 as Ar → 0 (Stokes, exactly) and
// Re_t → √Ar/c as Ar → ∞, i.e. C_D = 4 Ar/(3 Re_t²) → 4c²/3 = 0.4655 for a sphere (the Newton
// form's 0.44 is 6 % lower). Smooth for every Ar ≥ 0; dRe_t/dAr = 1/18 at Ar = 0.
// Parameter: φ_s ∈ [0.5, 1] (default 1, a sphere), a double like every law's parameter.
// Validity: the fit's sphericities 0.5–1 and the drag data below the drag crisis, Re_t ≲ 2.6·10⁵.
struct HaiderLevenspielTerminalVelocity : ArchimedesCorrelation<HaiderLevenspielTerminalVelocity> {
  double sphericity;  // φ_s

  constexpr explicit HaiderLevenspielTerminalVelocity(double sphericity = 1) : sphericity(sphericity) {}

  constexpr std::string_view name() const { return "HaiderLevenspielTerminalVelocity"; }
  constexpr std::string_view reference() const {
    return "Haider, A., Levenspiel, O. (1989) Powder Technol. 58, 63-70, doi:10.1016/0032-5910(89)80008-7";
  }
  constexpr Validity<2> validity() const {
    return {{{"sphericity", 0.5, 1.0}, {"terminal_reynolds", 0.0, 2.6e5}}};
  }

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr Arguments<T, 1> parameter_domain() const {
    return {{{"sphericity", T(sphericity), domains::closed(T(0.5L), T(1))}}};
  }
  static constexpr auto parameters() {
    return std::array{parameter<&HaiderLevenspielTerminalVelocity::sphericity>("sphericity")};
  }

  template <class S>
  FLUIDBED_HOST_DEVICE S reynolds_of_archimedes(const S& archimedes) const {
    using std::sqrt;
    using T = value_type_of<S>;
    const T c = FLUIDBED_DECIMAL(T, 2.3348) - FLUIDBED_DECIMAL(T, 1.7439) * T(sphericity);
    return archimedes / (18 + c * sqrt(archimedes));
  }
};

}  // namespace fluidbed::single_particle
