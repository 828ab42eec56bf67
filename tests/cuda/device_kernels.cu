// The per-cell entry points compiled as CUDA device code: kernels evaluate every
// monodisperse drag law (value and ∂β/∂ε, ∂β/∂w), every closure of every registry of the
// library (fluidbed::Registries: hot path and with_derivatives), invert moment sets to three and
// four nodes, evaluate the kinetic-theory set with its derivatives, the elastic force with its
// drag, the functions that are not closures (gas damping, buoyancy, virtual mass), the DQMOM
// sources and the multi-fluid closures of two classes.
// The host evaluates the same cells and, where a GPU is present, compares; where none is, the
// program reports a skip. nvcc reports a host function reached from device code, so that every
// warning being an error (run_device_compile_test.sh) also shows that no closure's device path
// reaches the checked entry points' throwing helpers (core/errors.hpp).
#include <cuda_runtime.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <tuple>
#include <vector>

#include "fluidbed/fluidbed.hpp"
#include "fluidbed/registries.hpp"

namespace {

using namespace fluidbed;

constexpr int cells = 256;
constexpr int outputs_per_law = 3;  // β (pressure-gradient buoyancy), ∂β/∂ε, ∂β/∂w

// The monodisperse family from its registry, every law and preset as its own type, so that the
// device sees every kernel.
FLUIDBED_HOST_DEVICE constexpr auto drag_family() { return drag::DragLaws::instances(); }
constexpr int laws = int(std::tuple_size_v<decltype(drag_family())>);

FLUIDBED_HOST_DEVICE drag::DragState<double> cell_state(int i) {
  const double u = (i + 0.5) / cells;
  return {0.38 + 0.62 * u, 1e-3 + 0.4 * u, {1.2, 1.8e-5}, 1.5e-4};
}

template <class Law>
FLUIDBED_HOST_DEVICE void store_drag(const Law& law, const drag::DragState<double>& state, double* out) {
  const auto with_derivatives = law.with_derivatives(state).pressure_gradient();
  out[0] = law(state).pressure_gradient();
  out[1] = with_derivatives.d_voidage;
  out[2] = with_derivatives.d_slip;
}

FLUIDBED_HOST_DEVICE void drag_cell(int i, double* out) {
  const auto state = cell_state(i);
  double* slot = out + i * laws * outputs_per_law;
  std::apply([&](const auto&... law) { ((store_drag(law, state, slot), slot += outputs_per_law), ...); },
             drag_family());
}

// Every closure of every registry, called in one cell with arguments inside its domain, in
// the calling shape of its registry. A registry not listed here stops the build, so that a new
// family is added here too.
template <class T>
FLUIDBED_HOST_DEVICE double number_of(const T& value) {
  if constexpr (requires { value.pressure_gradient(); })
    return value.pressure_gradient();  // a drag coefficient β
  else if constexpr (requires { value.pressure; })
    return value.pressure + value.viscosity;  // a frictional stress (p_f, μ_f)
  else
    return value;
}

template <class Registry, class... Listed>
constexpr bool is_one_of = (std::is_same_v<Registry, Listed> || ...);

template <class Registry, class Law>
FLUIDBED_HOST_DEVICE double evaluate_closure(const Law& law, int i) {
  using namespace kinetic_theory;
  const double u = (i + 0.5) / cells;
  const drag::DragState<double> drag_state = cell_state(i);
  const Particles<double> particles{2500.0, 1.5e-4}, small{2500.0, 1e-4};
  const elastic::EquilibriumState<double> equilibrium{drag_state.voidage, drag_state.fluid, particles, 2.0};
  const double phi = 0.05 + 0.5 * u, theta = 1e-4 + 0.01 * u, x = 0.3 + 100 * u;  // x: Re, Re_t, Ar or p_f
  const GranularMaterial<double> m{2e-4, 2500.0, 0.9};
  const StrainRate<double> rate{-0.5 + u, 4.0 + u};
  const CarnahanStarling rdf;
  const double g0 = rdf(phi), slip = 0.01 + u, gas_viscosity = 1.8e-5, beta = 1e4;
  const std::array<double, 2> fractions{0.6 * phi, 0.4 * phi}, diameters{1.5e-4, 1e-4};
  const std::span<const double> diameter_span(diameters);
  if constexpr (is_one_of<Registry, single_particle::DragCoefficients, settling::RichardsonZakiExponents>) {
    (void)law.with_derivatives(x);
    return law(x);
  } else if constexpr (std::is_same_v<Law, single_particle::SchillerNaumannTerminalVelocity>) {
    return 0;  // host only: Re_t(Ar) by Boost.Math's TOMS 748, which has no device code
  } else if constexpr (is_one_of<Registry, single_particle::TerminalVelocities, fluidization::MinimumFluidizations>) {
    (void)law.with_derivatives(x);
    return law(drag_state.fluid, particles, 9.81);
  } else if constexpr (std::is_same_v<Registry, drag::DragLaws>) {
    (void)law.with_derivatives(drag_state);
    return number_of(law(drag_state));
  } else if constexpr (std::is_same_v<Registry, elastic::ElasticModuli>) {
    if constexpr (requires { law(equilibrium); }) {
      (void)law.with_derivatives(equilibrium);
      return law(equilibrium);
    } else {  // off equilibrium
      (void)law.with_derivatives(drag_state);
      return law(drag_state);
    }
  } else if constexpr (is_one_of<Registry, RadialDistributions, FrictionalPressures>) {
    (void)law.with_derivatives(phi);
    return law(phi);
  } else if constexpr (std::is_same_v<Registry, MixtureRadialDistributions>) {
    (void)law.with_derivatives(fractions, diameter_span, 0, 1);
    return law(std::span<const double>(fractions), diameter_span, 0, 1);
  } else if constexpr (is_one_of<Registry, GranularPressures, ShearViscosities, BulkViscosities, Conductivities,
                                 Dissipations>) {
    (void)law.with_derivatives(phi, theta, rdf, m);
    return law(phi, theta, g0, m);
  } else if constexpr (std::is_same_v<Registry, FrictionalViscosities>) {
    (void)law.with_derivatives(x, rate);
    return law(x, rate);
  } else if constexpr (std::is_same_v<Registry, FrictionalStresses>) {
    (void)law.with_derivatives(phi, theta, m.diameter, rate);
    return number_of(law(phi, theta, m.diameter, rate));
  } else if constexpr (std::is_same_v<Registry, GasExchangeSources>) {
    if constexpr (std::is_same_v<Law, KochSanganiSource>) {
      (void)law.with_derivatives(phi, theta, rdf, slip, gas_viscosity, m);
      return law(phi, theta, g0, slip, gas_viscosity, m);
    } else {
      (void)law.with_derivatives(phi, theta, beta, slip, m);
      return law(phi, theta, beta, slip, m);
    }
  } else if constexpr (std::is_same_v<Registry, SolidSolidDrags>) {
    (void)law.with_derivatives(0.6 * phi, 0.4 * phi, particles, small, 0.9, g0, slip);
    return law(0.6 * phi, 0.4 * phi, particles, small, 0.9, g0, slip);
  } else if constexpr (std::is_same_v<Registry, WallBoundaryConditions>) {
    (void)law.with_derivatives(phi, theta, rdf, slip, m);
    return law(phi, theta, g0, slip, m).energy_flux;
  } else {
    static_assert(sizeof(Law) == 0, "a registry without a calling shape in evaluate_closure");
    return 0;
  }
}

template <class Registry>
constexpr int closures_in() {
  return int(std::tuple_size_v<decltype(Registry::instances())>);
}
constexpr int registered_closures = [] {
  int n = 0;
  Registries::for_each([&](auto registry) { n += closures_in<typename decltype(registry)::type>(); });
  return n;
}();

FLUIDBED_HOST_DEVICE void registry_cell(int i, double* out) {
  double* slot = out + i * registered_closures;
  Registries::for_each([&](auto registry) {
    using Registry = typename decltype(registry)::type;
    std::apply([&](const auto&... law) { ((*slot++ = evaluate_closure<Registry>(law, i)), ...); },
               Registry::instances());
  });
}

// Moments of a log-normal size distribution, mean 100–200 µm, spread 0.3, inverted to three
// nodes (the closed-form solver) and to four (the QL): nodes, weights and whether ok.
constexpr int quadrature_outputs = 2 * 3 + 1 + 2 * 4 + 1;

template <int N>
FLUIDBED_HOST_DEVICE double* store_quadrature(const moments::InversionResult<double, N>& r, double* out) {
  for (int k = 0; k < N; ++k) *out++ = r.quadrature.nodes[k];
  for (int k = 0; k < N; ++k) *out++ = r.quadrature.weights[k];
  *out++ = double(r.status == moments::InversionStatus::ok);
  return out;
}

FLUIDBED_HOST_DEVICE void quadrature_cell(int i, double* out) {
  const double mean = 100e-6 * (1 + double(i) / cells), spread = 0.3;
  std::array<double, 8> m{};
  for (int n = 0; n < 8; ++n) m[n] = std::exp(n * std::log(mean) + 0.5 * n * n * spread * spread);
  double* slot = out + i * quadrature_outputs;
  slot = store_quadrature(moments::invert<3>(std::array<double, 6>{m[0], m[1], m[2], m[3], m[4], m[5]}), slot);
  store_quadrature(moments::invert<4>(m), slot);
}

FLUIDBED_HOST_DEVICE void kinetic_theory_cell(int i, double* out) {
  using namespace kinetic_theory;
  const double u = (i + 0.5) / cells;
  const ConstitutiveSet set{Ogawa{0.63}, LunPressure{}, SyamlalViscosity{}, SyamlalConductivity{}};
  const auto k = set.with_derivatives(0.6 * u, 1e-4 + 0.01 * u, GranularMaterial<double>{2e-4, 2500.0, 0.9});
  out[i * 3 + 0] = k.pressure.d_solid_fraction;
  out[i * 3 + 1] = k.shear_viscosity.d_granular_temperature;
  out[i * 3 + 2] = k.conductivity.value;
}

// The elastic force of seed 000 eq. 3.116 from one Re* solve, and a Richardson–Zaki exponent.
FLUIDBED_HOST_DEVICE void elastic_cell(int i, double* out) {
  const auto state = cell_state(i);
  const auto d = elastic::mazzei_lettieri_drag_and_sensitivity(state.voidage, state.slip, state.fluid, state.diameter);
  const Vector3<double> slip{0.0, 0.02, state.slip}, voidage_gradient{0.0, 1.0, 4.0};
  const auto force = elastic::elastic_force(scaled(d.beta, slip), voidage_gradient, d.sensitivity, state.diameter);
  out[i * 3 + 0] = force[1];
  out[i * 3 + 1] = force[2];
  out[i * 3 + 2] = settling::MazzeiExponent{}(1.0 + 10.0 * i);
}

// The functions that are not closures of a registry: the gas's damping of the fluctuations, the
// buoyancy and the virtual mass force (their checks pass names to the hot path too).
FLUIDBED_HOST_DEVICE void free_function_cell(int i, double* out) {
  const double u = (i + 0.5) / cells;
  const Vector3<double> gravity{0.0, 0.0, -9.81}, fluid_acceleration{0.1, 0.0, u}, particle_acceleration{0.0, u, 0.0};
  out[i * 3 + 0] = kinetic_theory::gas_damping(1e3 * u, 1e-3 + u);
  out[i * 3 + 1] = interaction::classical_buoyancy(0.5 * u, 1.2, gravity)[2];
  out[i * 3 + 2] = interaction::virtual_mass_force(0.5 * u, 1.2, fluid_acceleration, particle_acceleration)[2];
}

// DQMOM sources of four nodes (moment sources with the condition number, growth as point
// functionals, fractional orders) and the multi-fluid closures of two classes.
constexpr int polydisperse_outputs = 3 * 8 + 1 + 3;

FLUIDBED_HOST_DEVICE void polydisperse_cell(int i, double* out) {
  const double u = (i + 0.5) / cells;
  const std::array<double, 4> xi{75e-6, 103e-6 + 50e-6 * u, 240e-6, 355e-6}, phi{0.1, 0.2, 0.15, 0.05},
      growth{1e-7, -2e-7, 3e-7 * u, 1e-8};
  const std::array<double, 8> s{1e-3, 2e-7, 3e-11 * u, 5e-15, -1e-18, 2e-22, 7e-26, 1e-30},
      orders{0, 1, 0.5, 1.5, 2, 2.5, 3, 3.5};
  const moments::dqmom::System<double, 4> system{std::span<const double>(xi), std::span<const double>(phi)};
  const auto terms = moments::dqmom::growth_terms<double, 4>(moments::dqmom::Weights::volume_fraction,
                                                             std::span<const double>(phi), std::span<const double>(xi),
                                                             std::span<const double>(growth));
  const auto from_moments = system.solve(std::span<const double>(s));
  const auto from_terms = system.solve(std::span<const moments::dqmom::PointSource<double>>(terms));
  const auto from_orders = moments::dqmom::solve_orders<double, 4>(std::span<const double>(xi), std::span<const double>(phi),
                                                                   std::span<const double>(orders), std::span<const double>(s));
  double* slot = out + i * polydisperse_outputs;
  for (const auto* c : {&from_moments, &from_terms, &from_orders})
    for (int k = 0; k < 4; ++k) *slot++ = c->weight[k], *slot++ = c->weighted_node[k];
  *slot++ = from_moments.condition;
  const polydisperse::MultiFluidState<double, 2> state{
      2, {0.2, 0.2 * u}, {100e-6, 300e-6}, {2500.0, 2500.0}, {{{0, 0, 0.01}, {0, 0, -0.02 * u}}}, {1.2, 1.8e-5}, {0, 0, 0.3}};
  const auto coefficients = polydisperse::ClassClosures<>{}(state);
  *slot++ = coefficients.gas_particle(0).pressure_gradient();
  *slot++ = coefficients.gas_particle(1).classical();
  *slot++ = coefficients.solid_solid(0, 1);
}

template <void (*Cell)(int, double*)>
__global__ void per_cell_kernel(double* out) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < cells) Cell(i, out);
}

// Runs `Cell` on the device and on the host; the largest relative difference.
template <void (*Cell)(int, double*)>
double device_host_difference(int per_cell, const char* what) {
  const std::size_t size = std::size_t(cells) * per_cell;
  std::vector<double> host(size), device(size);
  for (int i = 0; i < cells; ++i) Cell(i, host.data());
  double* buffer = nullptr;
  // NaN everywhere first (all bits set), so that a value the kernel did not write shows.
  cudaError_t status = cudaMalloc(&buffer, size * sizeof(double));
  if (status == cudaSuccess) status = cudaMemset(buffer, 0xff, size * sizeof(double));
  if (status == cudaSuccess) {
    per_cell_kernel<Cell><<<(cells + 127) / 128, 128>>>(buffer);
    status = cudaGetLastError();
  }
  if (status == cudaSuccess) status = cudaDeviceSynchronize();
  if (status == cudaSuccess)
    status = cudaMemcpy(device.data(), buffer, size * sizeof(double), cudaMemcpyDeviceToHost);
  cudaFree(buffer);
  if (status != cudaSuccess) {
    std::printf("%-15s the kernel did not run: %s\n", what, cudaGetErrorString(status));
    return INFINITY;
  }
  double worst = 0;
  std::size_t worst_at = 0;
  for (std::size_t j = 0; j < size; ++j) {
    const double scale = std::fmax(std::fabs(host[j]), 1e-300);
    const double difference = std::isfinite(device[j]) ? std::fabs(device[j] - host[j]) / scale : INFINITY;
    if (!(difference <= worst)) worst = difference, worst_at = j;
  }
  std::printf("%-15s %6zu values, largest relative device-host difference %.2e (value %zu: device %.17g, host "
              "%.17g)\n",
              what, size, worst, worst_at, device[worst_at], host[worst_at]);
  return worst;
}

}  // namespace

// Exit status 77 (ctest's SKIP_RETURN_CODE) when there is no device: the kernels compiled but
// did not run, and that is a skip, never a pass.
int main() {
  int devices = 0;
  const cudaError_t query = cudaGetDeviceCount(&devices);
  if (query != cudaSuccess || devices == 0) {
    std::printf("skipped: no CUDA device to run the kernels on (cudaGetDeviceCount: %s, %d devices); they compiled as "
                "device code, which the compile test checks\n",
                cudaGetErrorString(query), devices);
    return 77;
  }
  // Device and host may contract a·b + c differently (FMA), and libdevice's pow/exp differ
  // from glibc's in the last bits; the Re* solve of Mazzei–Lettieri and the eigenvalue
  // iteration amplify that by a few orders, hence 1e-10 rather than exact equality.
  constexpr double tolerance = 1e-10;
  const double worst[] = {device_host_difference<drag_cell>(laws * outputs_per_law, "drag"),
                          device_host_difference<registry_cell>(registered_closures, "registries"),
                          device_host_difference<quadrature_cell>(quadrature_outputs, "inversion"),
                          device_host_difference<kinetic_theory_cell>(3, "kinetic theory"),
                          device_host_difference<elastic_cell>(3, "elastic force"),
                          device_host_difference<free_function_cell>(3, "free functions"),
                          device_host_difference<polydisperse_cell>(polydisperse_outputs, "polydisperse")};
  for (double w : worst)
    if (!(w <= tolerance)) {
      std::printf("FAILED: device and host differ by more than %.0e\n", tolerance);
      return 1;
    }
  return 0;
}
