// fluidbed — a sphere settling in a fluid under gravity: its domain, and the calling shape of
// every correlation Re(Ar) that gives a velocity (terminal velocities here, minimum
// fluidization velocities in fluidization/).
//
//   Ar = ρ_f (ρ_p − ρ_f) g d³ / μ_f²,   u = Re μ_f / (ρ_f d)
//
// (Re = ρ_f u d / μ_f, the Reynolds number of that velocity: Re_t = ρ_f u_t d/μ_f for the
// terminal velocity, Re_mf = ρ_f u_mf d/μ_f for minimum fluidization.) Heavier-than-fluid
// particles only (ρ_p > ρ_f: Ar > 0). Standard library only.
#pragma once

#include <string_view>

#include "../core/closure.hpp"
#include "../core/config.hpp"
#include "../core/domain.hpp"
#include "../core/dual.hpp"
#include "../core/errors.hpp"
#include "../properties.hpp"

namespace fluidbed::single_particle {

// The domain of a settling system, declared once: ρ_f, μ_f, d, g finite and > 0, ρ_p finite
// and > ρ_f. What every terminal velocity, minimum fluidization velocity, bed expansion and
// homogeneous suspension (elastic/) asserts (hot path) or checks (require_within).
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 5> settling_domain(const Fluid<T>& fluid, const Particles<T>& particles,
                                                               const T& gravity) {
  return {{{"fluid.density", fluid.density, domains::positive<T>()},
           {"fluid.viscosity", fluid.viscosity, domains::positive<T>()},
           {"particles.diameter", particles.diameter, domains::positive<T>()},
           {"gravity", gravity, domains::positive<T>()},
           {"particles.density", particles.density, domains::greater_than(fluid.density),
            "must be finite and > fluid.density: heavier-than-fluid particles only"}}};
}

// The domain of Ar, declared once: finite and >= 0.
template <class T>
FLUIDBED_HOST_DEVICE constexpr Arguments<T, 1> archimedes_domain(const T& archimedes) {
  return {{{"archimedes", archimedes, domains::non_negative<T>()}}};
}

// u = Re μ_f / (ρ_f d).
template <class T>
FLUIDBED_HOST_DEVICE constexpr T velocity_from_reynolds(const T& reynolds, const Fluid<T>& fluid,
                                                        const Particles<T>& particles) {
  return reynolds * fluid.viscosity / (fluid.density * particles.diameter);
}

// Re and dRe/dAr.
template <class T>
struct ReynoldsWithDerivative {
  T value;         // Re
  T d_archimedes;  // dRe/dAr
};

// CRTP base of the correlations Re(Ar). Law provides name(), reference(), validity(),
//   template <class S> S reynolds_of_archimedes(const S& archimedes) const;   the kernel
// (S = T or Dual<T, 1>; a law solved numerically instead provides
//   template <class T> ReynoldsWithDerivative<T> reynolds_with_derivative(const T&) const;)
// and, if it has parameters, `template <class T> Arguments<T, N> parameter_domain() const`.
// The base gives
//   law.reynolds(Ar)                 Re (hot path; Ar >= 0 and the parameters asserted)
//   law(fluid, particles, g)         the velocity u = Re(Ar) μ_f/(ρ_f d) (hot path)
//   law.with_derivatives(Ar)         Re and dRe/dAr
//   law.checked(fluid, particles, g), law.checked_reynolds(Ar), law.checked_with_derivatives(Ar)
//                                    throw std::domain_error naming the first argument outside
//                                    its domain (settling_domain, archimedes_domain, parameters).
template <class Law>
struct ArchimedesCorrelation {
  // The domain of a call with Ar: Ar's, then the law's parameters'.
  template <class T>
  FLUIDBED_HOST_DEVICE constexpr auto domain(const T& archimedes) const {
    return join(archimedes_domain(archimedes), parameter_domain_of<T>(self()));
  }

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr T reynolds(const T& archimedes) const {
    FLUIDBED_EXPECTS(within(domain(archimedes)));
    return self().reynolds_of_archimedes(archimedes);
  }

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr T operator()(const Fluid<T>& fluid, const Particles<T>& particles,
                                              const T& gravity = standard_gravity_as<T>()) const {
    FLUIDBED_EXPECTS(within(settling_domain(fluid, particles, gravity)));
    return velocity_from_reynolds(reynolds(archimedes(fluid, particles, gravity)), fluid, particles);
  }

  template <class T>
  FLUIDBED_HOST_DEVICE constexpr ReynoldsWithDerivative<T> with_derivatives(const T& archimedes) const {
    FLUIDBED_EXPECTS(within(domain(archimedes)));
    if constexpr (requires { self().reynolds_with_derivative(archimedes); }) {
      return self().reynolds_with_derivative(archimedes);
    } else {
      const Dual<T, 1> re = self().reynolds_of_archimedes(Dual<T, 1>::variable(archimedes, 0));
      return {re.value, re.derivative[0]};
    }
  }

  template <class T>
  T checked(const Fluid<T>& fluid, const Particles<T>& particles, const T& gravity = standard_gravity_as<T>()) const {
    require_within(self().name(), join(settling_domain(fluid, particles, gravity), parameter_domain_of<T>(self())));
    return (*this)(fluid, particles, gravity);
  }

  template <class T>
  T checked_reynolds(const T& archimedes) const {
    require_within(self().name(), domain(archimedes));
    return reynolds(archimedes);
  }

  template <class T>
  ReynoldsWithDerivative<T> checked_with_derivatives(const T& archimedes) const {
    require_within(self().name(), domain(archimedes));
    return with_derivatives(archimedes);
  }

 private:
  FLUIDBED_HOST_DEVICE constexpr const Law& self() const { return static_cast<const Law&>(*this); }
};

}  // namespace fluidbed::single_particle
