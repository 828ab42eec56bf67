// A downstream program: evaluates a drag law chosen by name at run time and a kinetic-theory set
// through the public headers and exits non-zero if the numbers are not the published ones. It
// includes the whole drag family and the kinetic theory, which need neither Boost nor Eigen
// (run_consumer_tests.sh checks that on a machine without them).
#include <cmath>
#include <cstdio>
#include <fluidbed/drag/any_drag_law.hpp>
#include <fluidbed/kinetic_theory.hpp>

int main() {
  // Ergun at ε = 0.5, w = 0.1 m/s, air, d = 0.5 mm: 150 φ²μ/(εd²) + 1.75 φρw/d.
  const fluidbed::drag::DragState<double> cell{0.5, 0.1, {1.2, 1.8e-5}, 5e-4};
  const double beta = evaluate(fluidbed::drag::make_drag_law("Ergun"), cell).pressure_gradient();
  // Lun et al. (1984) pressure ρ_s φ Θ [1 + 2(1 + e) φ g0] with Ogawa's g0 = 1/(1 − (φ/0.63)^⅓)
  // = 4.56406 at φ = 0.3, Θ = 0.01 m²/s², e = 0.9, ρ_s = 2500 kg/m³: 46.5227 Pa (seed 001 eqs. 21, 24).
  using namespace fluidbed::kinetic_theory;
  const ConstitutiveSet set{Ogawa{0.63}, LunPressure{}, GidaspowViscosity{}, GidaspowConductivity{}};
  const double pressure = set(0.3, 0.01, GranularMaterial<double>{500e-6, 2500.0, 0.9}).pressure;
  std::printf("beta = %.6g kg/m3/s, p_s = %.6g Pa\n", beta, pressure);
  const bool ok = std::abs(beta - 5610.0) < 1e-9 * 5610.0 && std::abs(pressure - 46.5227) < 1e-4;
  return ok ? 0 : 1;
}
