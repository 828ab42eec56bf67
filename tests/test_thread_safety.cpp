// Thread safety: the library has no global mutable state, so concurrent per-cell calls
// from many threads give bit-identical results to the same calls made serially. Run under
// AddressSanitizer/UndefinedBehaviorSanitizer with the rest of the suite.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <thread>
#include <vector>

#include "fluidbed/fluidbed.hpp"

namespace {

// One cell's worth of work across the families: a drag law chosen at run time with its
// derivatives, the kinetic-theory set with derivatives, and a three-node inversion.
double cell_result(std::size_t i) {
  using namespace fluidbed;
  const double u = (static_cast<double>(i % 997) + 0.5) / 997.0;
  const drag::DragState<double> state{0.4 + 0.55 * u, 1e-3 + 0.5 * u, {1.2, 1.8e-5}, 2e-4};
  const auto law = drag::make_drag_law(i % 2 ? "MazzeiLettieri" : "Beetstra");
  const double beta = drag::evaluate_with_derivatives(law, state).pressure_gradient().d_voidage;

  using namespace kinetic_theory;
  const ConstitutiveSet set{Ogawa{0.63}, LunPressure{}, SyamlalViscosity{}, SyamlalConductivity{}};
  const auto k = set.with_derivatives(0.6 * u, 1e-4 + 0.01 * u, GranularMaterial<double>{2e-4, 2500.0, 0.9});

  const double mean = 100e-6 * (1 + u), spread = 0.3;
  std::array<double, 6> m{};
  for (int n = 0; n < 6; ++n) m[n] = std::exp(n * std::log(mean) + 0.5 * n * n * spread * spread);
  const auto q = moments::invert<3>(m);
  return beta + k.pressure.d_solid_fraction + k.conductivity.d_granular_temperature + q.quadrature.nodes[2];
}

}  // namespace

TEST_CASE("concurrent per-cell calls from 8 threads equal the serial results bit for bit") {
  constexpr std::size_t cells = 4000, threads = 8;
  std::vector<double> serial(cells), parallel(cells);
  for (std::size_t i = 0; i < cells; ++i) serial[i] = cell_result(i);
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < threads; ++t)
    pool.emplace_back([&parallel, t] {
      for (std::size_t i = t; i < cells; i += threads) parallel[i] = cell_result(i);
    });
  for (auto& thread : pool) thread.join();
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < cells; ++i) mismatches += serial[i] != parallel[i];
  CHECK(mismatches == 0);
  CHECK(std::isfinite(serial[cells / 2]));
}
