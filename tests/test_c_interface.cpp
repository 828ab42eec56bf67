// The C interface (bindings/c, fluidbed_c.h) against the C++ library it wraps: every row of the
// reference tables of the families it offers, run through both, agrees bit for bit (values from
// the checked entry points, derivatives from checked_with_derivatives; to rounding where this
// test is compiled with floating-point contraction, see same_bits); bad input gives the
// checked API's error as a status, the failing cell and the same message, never a crash or a NaN
// without a status; the catalogue, metadata and parameters are the registries'; one handle is
// evaluated from several threads at once.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "fluidbed/moments/batched.hpp"
#include "fluidbed/moments/correction.hpp"
#include "fluidbed/moments/dqmom.hpp"
#include "fluidbed/moments/dqmom_batched.hpp"
#include "fluidbed/moments/realizability.hpp"
#include "fluidbed/registries.hpp"
#include "fluidbed_c.h"
#include "kinetic_theory_table_names.hpp"
#include "moment_reference.hpp"
#include "reference_table.hpp"

namespace {

using namespace fluidbed;

struct ClosureDeleter {
  void operator()(fluidbed_closure* c) const { fluidbed_closure_destroy(c); }
};
using Handle = std::unique_ptr<fluidbed_closure, ClosureDeleter>;

Handle create(const std::string& name) {
  fluidbed_closure* closure = nullptr;
  fluidbed_error error{};
  const fluidbed_status status = fluidbed_closure_create(name.c_str(), &closure, &error);
  REQUIRE_MESSAGE(status == FLUIDBED_OK, error.message);
  return Handle(closure);
}

// Equal bits (a NaN equal to a NaN): what "bit for bit" means. This test and the bindings are
// compiled without floating-point contraction (-ffp-contract=off, tests/CMakeLists.txt), so that
// its C++ calls and the C interface's perform the same operations whatever the target.
template <class T>
bool same_bits(T a, T b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::memcmp(&a, &b, sizeof a) == 0;
}

constexpr fluidbed_buoyancy c_conventions[] = {FLUIDBED_BUOYANCY_CLASSICAL, FLUIDBED_BUOYANCY_PRESSURE_GRADIENT};

// compare(std::integral_constant<int, N>{}, support) for N = 1 … FLUIDBED_MAX_NODES on both
// supports, or compare(std::integral_constant<int, N>{}) where it takes no support.
template <class Compare>
void for_each_node_count(Compare&& compare) {
  const auto counts = [&](auto... support) {
    [&]<int... M>(std::integer_sequence<int, M...>) {
      (compare(std::integral_constant<int, M + 1>{}, support...), ...);
    }(std::make_integer_sequence<int, FLUIDBED_MAX_NODES>{});
  };
  if constexpr (std::is_invocable_v<Compare&, std::integral_constant<int, 1>>)
    counts();
  else
    for (const fluidbed_support support : {FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, FLUIDBED_SUPPORT_REAL_LINE})
      counts(support);
}

}  // namespace

TEST_CASE("C interface: every drag reference row, both conventions, value and derivatives bit for bit") {
  const test::ReferenceTable table("drag_reference.csv");
  // The table's rows by law, as arrays of cells (structure of arrays, as a host passes them).
  struct Cells {
    std::vector<double> voidage, slip, density, viscosity, diameter;
  };
  std::map<std::string, Cells> by_law;
  for (std::size_t row = 0; row < table.size(); ++row) {
    Cells& c = by_law[table.text(row, "law")];
    c.voidage.push_back(table.number(row, "voidage"));
    c.slip.push_back(table.number(row, "slip"));
    c.density.push_back(table.number(row, "fluid_density"));
    c.viscosity.push_back(table.number(row, "fluid_viscosity"));
    c.diameter.push_back(table.number(row, "diameter"));
  }
  CHECK(by_law.size() == drag::DragLaws::size);
  std::size_t compared = 0;
  for (const auto& entry : by_law) {  // no structured binding: clang 14 cannot capture one
    const std::string& name = entry.first;
    const Cells& c = entry.second;
    CAPTURE(name);
    const Handle law = create(name);
    const drag::DragLaws::Variant cpp = drag::DragLaws::make(name);
    const std::size_t n = c.voidage.size();
    for (const fluidbed_buoyancy convention : c_conventions) {
      const auto b = convention == FLUIDBED_BUOYANCY_CLASSICAL ? drag::Buoyancy::classical
                                                               : drag::Buoyancy::pressure_gradient;
      std::vector<double> beta(n), d_voidage(n), d_slip(n), d_force(n), beta_only(n);
      fluidbed_error error{};
      REQUIRE(fluidbed_drag(law.get(), convention, n, c.voidage.data(), c.slip.data(), c.density.data(),
                            c.viscosity.data(), c.diameter.data(), beta.data(), d_voidage.data(), d_slip.data(),
                            d_force.data(), &error) == FLUIDBED_OK);
      REQUIRE(fluidbed_drag(law.get(), convention, n, c.voidage.data(), c.slip.data(), c.density.data(),
                            c.viscosity.data(), c.diameter.data(), beta_only.data(), nullptr, nullptr, nullptr,
                            &error) == FLUIDBED_OK);
      for (std::size_t i = 0; i < n; ++i) {
        const drag::DragState<double> state{c.voidage[i], c.slip[i], {c.density[i], c.viscosity[i]}, c.diameter[i]};
        std::visit(
            [&](const auto& l) {
              const auto with = l.checked_with_derivatives(state);
              CHECK(same_bits(beta[i], l.checked(state).in(b)));
              CHECK(same_bits(beta_only[i], beta[i]));
              CHECK(same_bits(d_voidage[i], with.in(b).d_voidage));
              CHECK(same_bits(d_slip[i], with.in(b).d_slip));
              CHECK(same_bits(d_force[i], with.force_slip_derivative(b)));
            },
            cpp);
        ++compared;
      }
    }
  }
  CHECK(compared == 2 * table.size());
}

TEST_CASE("C interface: in float, the drag reference states and the kinetic-theory rows bit for bit with the C++ float calls") {
  const test::ReferenceTable table("drag_reference.csv");
  std::size_t compared = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const std::string name = table.text(row, "law");
    const auto f = [&](const char* column) { return static_cast<float>(table.number(row, column)); };
    const float voidage = f("voidage"), slip = f("slip"), density = f("fluid_density"),
                viscosity = f("fluid_viscosity"), diameter = f("diameter");
    const drag::DragState<float> state{voidage, slip, {density, viscosity}, diameter};
    const bool representable =  // a state whose β overflows float is the checked API's error in float too
        std::visit([&](const auto& l) { return std::isfinite(l(state).classical()); }, drag::DragLaws::make(name));
    if (!representable) continue;
    const Handle law = create(name);
    float beta = 0, d_voidage = 0;
    fluidbed_error error{};
    REQUIRE_MESSAGE(fluidbed_drag_f(law.get(), FLUIDBED_BUOYANCY_CLASSICAL, 1, &voidage, &slip, &density, &viscosity,
                                    &diameter, &beta, &d_voidage, nullptr, nullptr, &error) == FLUIDBED_OK,
                    error.message);
    std::visit(
        [&](const auto& l) {
          CHECK(same_bits(beta, l.checked(state).classical()));
          CHECK(same_bits(d_voidage, l.checked_with_derivatives(state).classical().d_voidage));
        },
        drag::DragLaws::make(name));
    ++compared;
  }
  CHECK(compared > table.size() * 9 / 10);

  const Handle viscosity = create("GidaspowViscosity"), radial = create("CarnahanStarling");
  const float phi = 0.3f, theta = 0.01f, d = 3e-4f, rho = 2500.0f, e = 0.9f;
  float value = 0, d_phi = 0, d_theta = 0;
  REQUIRE(fluidbed_constitutive_f(viscosity.get(), radial.get(), 1, &phi, &theta, &d, &rho, &e, &value, &d_phi,
                                  &d_theta, nullptr) == FLUIDBED_OK);
  const kinetic_theory::GranularMaterial<float> material{d, rho, e};
  const kinetic_theory::CarnahanStarling g0;
  const auto with = kinetic_theory::GidaspowViscosity{}.checked_with_derivatives(phi, theta, g0, material);
  CHECK(same_bits(value, kinetic_theory::GidaspowViscosity{}.checked(phi, theta, g0.checked(phi), material)));
  CHECK(same_bits(d_phi, with.d_solid_fraction));
  CHECK(same_bits(d_theta, with.d_granular_temperature));
}

TEST_CASE("C interface: the sphere drag coefficients, terminal velocities, u_mf and Richardson-Zaki rows bit for bit") {
  const test::ReferenceTable cd("cd_reference.csv");
  for (std::size_t row = 0; row < cd.size(); ++row) {
    const std::string name = cd.text(row, "law") + "Coefficient";
    CAPTURE(name);
    const Handle law = create(name);
    const double re = cd.number(row, "reynolds");
    double value = 0, slope = 0;
    REQUIRE(fluidbed_sphere_drag_coefficient(law.get(), 1, &re, &value, &slope, nullptr) == FLUIDBED_OK);
    std::visit(
        [&](const auto& l) {
          CHECK(same_bits(value, l.checked(re)));
          CHECK(same_bits(slope, l.checked_with_derivatives(re).d_reynolds));
        },
        single_particle::DragCoefficients::make(name));
  }

  const test::ReferenceTable settling("settling_reference.csv");
  // quantity -> (closure, the parameter the table's param2 sets, if any)
  const std::map<std::string, std::pair<std::string, std::string>> closures{
      {"rz_exponent_mazzei", {"MazzeiExponent", ""}},
      {"rz_exponent_rowe1987", {"RoweExponent", ""}},
      {"rz_exponent_garside_aldibouni1977", {"GarsideAlDibouniExponent", ""}},
      {"rz_exponent_khan_richardson1989", {"KhanRichardsonExponent", "wall_ratio"}},
      {"rz_exponent_richardson_zaki1954", {"RichardsonZaki1954Exponent", "wall_ratio"}},
      {"terminal_velocity_stokes", {"StokesTerminalVelocity", ""}},
      {"terminal_velocity_newton", {"NewtonTerminalVelocity", ""}},
      {"terminal_velocity_dallavalle", {"DallavalleTerminalVelocity", ""}},
      {"terminal_velocity_schillernaumann", {"SchillerNaumannTerminalVelocity", ""}},
      {"remf_ergun", {"ErgunMinimumFluidization", "voidage"}},
      {"remf_wenyu1966", {"WenYuMinimumFluidization", ""}}};
  std::size_t compared = 0;
  for (std::size_t row = 0; row < settling.size(); ++row) {
    const auto found = closures.find(settling.text(row, "quantity"));
    if (found == closures.end()) continue;  // bed expansion and u_mf in m/s: not closures of the C interface
    const std::string& name = found->second.first;
    const std::string& parameter = found->second.second;
    CAPTURE(name);
    const Handle law = create(name);
    const double p1 = settling.number(row, "param1"), p2 = settling.number(row, "param2");
    if (!parameter.empty()) REQUIRE(fluidbed_closure_set_parameter(law.get(), parameter.c_str(), p2, nullptr) == FLUIDBED_OK);
    double x = p1;  // Re_t or Ar; the terminal-velocity rows give the fluid and the particles
    if (name.ends_with("TerminalVelocity")) {
      const Fluid<double> fluid{p1, p2};
      const Particles<double> particles{settling.number(row, "param3"), settling.number(row, "param4")};
      x = archimedes(fluid, particles);
    }
    double value = 0, slope = 0;
    const auto compare = [&](const auto& cpp) {
      std::visit(
          [&](auto l) {
            if (!parameter.empty()) set_parameter_checked(l, parameter, p2);
            if constexpr (requires { l.checked_reynolds(x); }) {
              REQUIRE(fluidbed_reynolds_of_archimedes(law.get(), 1, &x, &value, &slope, nullptr) == FLUIDBED_OK);
              CHECK(same_bits(value, l.checked_reynolds(x)));
              CHECK(same_bits(slope, l.checked_with_derivatives(x).d_archimedes));
            } else {
              REQUIRE(fluidbed_richardson_zaki_exponent(law.get(), 1, &x, &value, &slope, nullptr) == FLUIDBED_OK);
              CHECK(same_bits(value, l.checked(x)));
              CHECK(same_bits(slope, l.checked_with_derivatives(x).d_argument));
            }
          },
          cpp);
    };
    if (auto t = single_particle::TerminalVelocities::find(name)) compare(*t);
    else if (auto m = fluidization::MinimumFluidizations::find(name)) compare(*m);
    else compare(settling::RichardsonZakiExponents::make(name));
    ++compared;
  }
  CHECK(compared == 96);
}

TEST_CASE("C interface: every one-class kinetic-theory reference row bit for bit, derivatives included") {
  namespace kt = kinetic_theory;
  const auto set_both = [](fluidbed_closure* handle, auto& law, const std::string& parameter, double value) {
    if (!get_parameter(law, parameter)) return;
    REQUIRE(fluidbed_closure_set_parameter(handle, parameter.c_str(), value, nullptr) == FLUIDBED_OK);
    set_parameter_checked(law, parameter, value);
  };
  const test::ReferenceTable table("ktgf_reference.csv");
  std::size_t radial_rows = 0, constitutive_rows = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const std::string function = table.text(row, "function"), variant = table.text(row, "variant");
    const double phi = table.number(row, "solid_fraction"), extra = table.number(row, "extra");
    double value = 0, slope = 0, d_theta = 0;
    if (function == "radial_distribution") {
      const std::string name = test::library_name(test::radial_distribution_names, variant);
      CAPTURE(name);
      const Handle law = create(name);
      auto cpp = kt::RadialDistributions::make(name);
      std::visit([&](auto& l) { set_both(law.get(), l, "max_packing", extra); }, cpp);
      REQUIRE(fluidbed_of_solid_fraction(law.get(), 1, &phi, &value, &slope, nullptr) == FLUIDBED_OK);
      std::visit(
          [&](const auto& l) {
            CHECK(same_bits(value, l.checked(phi)));
            CHECK(same_bits(slope, l.checked_with_derivatives(phi).d_solid_fraction));
          },
          cpp);
      ++radial_rows;
      continue;
    }
    // "gidaspow:ogawa": the law and the radial distribution it is evaluated with.
    const std::string author = variant.substr(0, variant.find(':'));
    const std::string table_name = function + ":" + author;
    if (std::none_of(test::constitutive_names.begin(), test::constitutive_names.end(),
                     [&](const test::TableName& n) { return n.table == table_name; }))
      continue;  // the kinetic and collisional parts, the algebraic temperature: not closures
    const std::string name = test::library_name(test::constitutive_names, table_name);
    const std::string radial_name =
        test::library_name(test::radial_distribution_names, variant.substr(variant.find(':') + 1));
    CAPTURE(name);
    const Handle law = create(name), radial = create(radial_name);
    const double theta = table.number(row, "granular_temperature"), e = table.number(row, "restitution"),
                 d = table.number(row, "diameter"), rho = table.number(row, "particle_density");
    REQUIRE(fluidbed_constitutive(law.get(), radial.get(), 1, &phi, &theta, &d, &rho, &e, &value, &slope, &d_theta,
                                  nullptr) == FLUIDBED_OK);
    const kt::GranularMaterial<double> material{d, rho, e};
    test::visit_by_name<int>(
        name,
        [&](auto l) {
          // The table's extra is the law's one parameter (Hrenya-Sinclair's L, Ahmadi-Ma's friction).
          if constexpr (parameters_of<decltype(l)>().size() == 1)
            set_both(law.get(), l, std::string(parameters_of<decltype(l)>()[0].name), extra);
          REQUIRE(fluidbed_constitutive(law.get(), radial.get(), 1, &phi, &theta, &d, &rho, &e, &value, &slope,
                                        &d_theta, nullptr) == FLUIDBED_OK);
          std::visit(
              [&](const auto& g0) {
                if constexpr (std::is_base_of_v<kt::ConstitutiveLaw<decltype(l)>, decltype(l)>) {
                  const auto with = l.checked_with_derivatives(phi, theta, g0, material);
                  CHECK(same_bits(value, l.checked(phi, theta, g0.checked(phi), material)));
                  CHECK(same_bits(slope, with.d_solid_fraction));
                  CHECK(same_bits(d_theta, with.d_granular_temperature));
                }
              },
              kt::RadialDistributions::make(radial_name));
          return 0;
        },
        std::type_identity<kt::GranularPressures>{}, std::type_identity<kt::ShearViscosities>{},
        std::type_identity<kt::BulkViscosities>{}, std::type_identity<kt::Conductivities>{},
        std::type_identity<kt::Dissipations>{});
    ++constitutive_rows;
  }
  CHECK(radial_rows == 214);
  CHECK(constitutive_rows == 1260);

  // Friction: the Johnson-Jackson and Schaeffer pressures, Schaeffer's viscosity of either
  // pressure, and the Srivastava-Sundaresan stress, with the table's parameters.
  const test::ReferenceTable friction("ktgf_friction_reference.csv");
  std::size_t friction_rows = 0;
  for (std::size_t row = 0; row < friction.size(); ++row) {
    const std::string function = friction.text(row, "function"), variant = friction.text(row, "variant");
    const double phi = friction.number(row, "solid_fraction"), theta = friction.number(row, "granular_temperature"),
                 d = friction.number(row, "diameter"), divergence = friction.number(row, "divergence"),
                 contraction = friction.number(row, "deviatoric_contraction");
    const auto with_table_parameters = [&](fluidbed_closure* handle, auto& law) {
      for (const char* p : {"min_fraction", "max_packing", "coefficient", "numerator_exponent", "denominator_exponent"})
        set_both(handle, law, p, friction.number(row, p));
      set_both(handle, law, "friction_angle", friction.number(row, "friction_angle_deg") * std::numbers::pi / 180);
    };
    const std::string pressure_name =
        variant.ends_with("johnson_jackson") ? "JohnsonJacksonPressure" : "SchaefferPressure";
    double value = 0, slope = 0, viscosity = 0, d_viscosity = 0;
    if (variant == "srivastava_sundaresan") {
      const Handle law = create("SrivastavaSundaresan");
      kt::SrivastavaSundaresan cpp = kt::SrivastavaSundaresan::registered()[0];
      with_table_parameters(law.get(), cpp);
      REQUIRE(fluidbed_frictional_stress(law.get(), 1, &phi, &theta, &d, &divergence, &contraction, &value,
                                         &viscosity, &slope, &d_viscosity, nullptr) == FLUIDBED_OK);
      const kt::StrainRate<double> rate{divergence, contraction};
      const auto stress = cpp.checked(phi, theta, d, rate);
      const auto with = cpp.checked_with_derivatives(phi, theta, d, rate);
      CHECK(same_bits(value, stress.pressure));
      CHECK(same_bits(viscosity, stress.viscosity));
      CHECK(same_bits(slope, with.pressure.d_solid_fraction));
      CHECK(same_bits(d_viscosity, with.viscosity.d_solid_fraction));
    } else {
      const Handle pressure = create(pressure_name);
      auto cpp_pressure = kt::FrictionalPressures::make(pressure_name);
      std::visit([&](auto& l) { with_table_parameters(pressure.get(), l); }, cpp_pressure);
      REQUIRE(fluidbed_of_solid_fraction(pressure.get(), 1, &phi, &value, &slope, nullptr) == FLUIDBED_OK);
      const double p_f = std::visit([&](const auto& l) { return l.checked(phi); }, cpp_pressure);
      CHECK(same_bits(value, p_f));
      CHECK(same_bits(slope, std::visit([&](const auto& l) { return l.checked_with_derivatives(phi).d_solid_fraction; },
                                        cpp_pressure)));
      if (function == "frictional_viscosity") {
        const Handle law = create("SchaefferViscosity");
        kt::SchaefferViscosity cpp = kt::SchaefferViscosity::registered()[0];
        with_table_parameters(law.get(), cpp);
        REQUIRE(fluidbed_frictional_viscosity(law.get(), 1, &p_f, &divergence, &contraction, &viscosity, &d_viscosity,
                                              nullptr) == FLUIDBED_OK);
        const kt::StrainRate<double> rate{divergence, contraction};
        CHECK(same_bits(viscosity, cpp.checked(p_f, rate)));
        CHECK(same_bits(d_viscosity, cpp.checked_with_derivatives(p_f, rate).d_frictional_pressure));
      }
    }
    ++friction_rows;
  }
  CHECK(friction_rows == friction.size());

  // A law of another kind than the function asked for, and no radial distribution.
  const Handle viscosity = create("GidaspowViscosity"), radial = create("CarnahanStarling");
  const double phi = 0.3, theta = 0.01, d = 3e-4, rho = 2500, e = 0.9;
  double out = 0;
  fluidbed_error error{};
  CHECK(fluidbed_constitutive(radial.get(), radial.get(), 1, &phi, &theta, &d, &rho, &e, &out, nullptr, nullptr,
                              &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(fluidbed_constitutive(viscosity.get(), viscosity.get(), 1, &phi, &theta, &d, &rho, &e, &out, nullptr, nullptr,
                              &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(std::string(error.message) == "fluidbed: constitutive: GidaspowViscosity is not a radial distribution");
  const double negative_theta = -1;
  CHECK(fluidbed_constitutive(viscosity.get(), radial.get(), 1, &phi, &negative_theta, &d, &rho, &e, &out, nullptr,
                              nullptr, &error) == FLUIDBED_DOMAIN_ERROR);
  CHECK(std::string(error.message).find("granular_temperature") != std::string::npos);
}

TEST_CASE("C interface: every moment set of the moments reference table, 1 to 8 nodes, bit for bit with invert_batched") {
  const auto sets = test::MomentReference::instance().moment_sets();  // the moments of each case
  REQUIRE(sets.size() > 10);
  std::size_t compared = 0;
  const auto compare = [&]<int N>(std::integral_constant<int, N>, fluidbed_support support) {
    std::vector<std::vector<double>> cells;  // every case with at least 2N moments, one cell each
    for (const auto& [name, m] : sets)
      if (m.size() >= 2 * N) cells.emplace_back(m.begin(), m.begin() + 2 * N);
    const std::size_t n = cells.size();
    std::vector<double> in(2 * N * n), nodes(N * n), weights(N * n);
    std::vector<int> sizes(n), status(n);
    for (std::size_t c = 0; c < n; ++c)
      for (int k = 0; k < 2 * N; ++k) in[k * n + c] = cells[c][k];
    REQUIRE(fluidbed_invert_moments(N, support, n, in.data(), nodes.data(), weights.data(), sizes.data(),
                                    status.data(), nullptr) == FLUIDBED_OK);
    moments::MomentBatch<double, N> batch;
    for (int k = 0; k < 2 * N; ++k) batch.moments[k] = std::span<const double>(in.data() + k * n, n);
    std::vector<double> cpp_nodes(N * n), cpp_weights(N * n);
    std::vector<int> cpp_sizes(n);
    std::vector<moments::InversionStatus> cpp_status(n);
    moments::QuadratureBatch<double, N> out;
    for (int i = 0; i < N; ++i) {
      out.nodes[i] = std::span<double>(cpp_nodes.data() + i * n, n);
      out.weights[i] = std::span<double>(cpp_weights.data() + i * n, n);
    }
    out.sizes = cpp_sizes;
    out.status = cpp_status;
    REQUIRE(moments::invert_batched(
        batch, out,
        support == FLUIDBED_SUPPORT_REAL_LINE ? moments::Support::real_line : moments::Support::positive_half_line));
    for (std::size_t i = 0; i < N * n; ++i) {
      CHECK(same_bits(nodes[i], cpp_nodes[i]));
      CHECK(same_bits(weights[i], cpp_weights[i]));
    }
    for (std::size_t c = 0; c < n; ++c) {
      CHECK(sizes[c] == cpp_sizes[c]);
      CHECK(status[c] == static_cast<int>(cpp_status[c]));
    }
    compared += n;
  };
  for_each_node_count(compare);
  CHECK(compared > 100);

  // Statuses, not errors, for cells that cannot be inverted; errors for what is not a cell's.
  const double empty_and_nan[4] = {0.0, std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0};  // 2 cells, N = 1
  double node[2], weight[2];
  int size[2], status[2];
  fluidbed_error error{};
  CHECK(fluidbed_invert_moments(1, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, 2, empty_and_nan, node, weight, size, status,
                                &error) == FLUIDBED_OK);
  CHECK(status[0] == FLUIDBED_INVERSION_ZERO_MASS);
  CHECK(status[1] == FLUIDBED_INVERSION_INVALID_INPUT);
  CHECK(fluidbed_invert_moments(9, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, 2, empty_and_nan, node, weight, size, status,
                                &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(std::string(error.message) == "fluidbed: invert_moments: 9 nodes; 1 to 8 are offered");
  CHECK(fluidbed_invert_moments(1, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, 2, empty_and_nan, node, nullptr, size, status,
                                &error) == FLUIDBED_INVALID_ARGUMENT);
}

namespace {
// The cells of the moments reference table with at least 2N moments, moment-major as the C
// interface reads them (moment k of cell c at [k n + c]), and each cell's own set.
struct MomentCells {
  std::vector<std::array<double, 16>> sets;
  std::vector<double> fields;
};
template <int N>
MomentCells reference_cells() {
  MomentCells cells;
  for (const auto& [name, m] : test::MomentReference::instance().moment_sets())
    if (m.size() >= 2 * N) {
      cells.sets.emplace_back();
      std::copy(m.begin(), m.begin() + 2 * N, cells.sets.back().begin());
    }
  const std::size_t n = cells.sets.size();
  cells.fields.resize(2 * N * n);
  for (std::size_t c = 0; c < n; ++c)
    for (int k = 0; k < 2 * N; ++k) cells.fields[k * n + c] = cells.sets[c][k];
  return cells;
}

// What fluidbed_invert_moments_with_accuracy writes for n cells of N nodes.
struct Inverted {
  std::vector<double> nodes, weights, node_errors, weight_errors, count_errors;
  std::vector<int> sizes, status;
  Inverted(int node_count, std::size_t n)
      : nodes(node_count * n),
        weights(node_count * n),
        node_errors(n),
        weight_errors(n),
        count_errors(n),
        sizes(n),
        status(n) {}
};

bool has_rule(int status) {
  return status == FLUIDBED_INVERSION_OK || status == FLUIDBED_INVERSION_REDUCED ||
         status == FLUIDBED_INVERSION_INACCURATE;
}

}  // namespace

TEST_CASE("C interface: the error estimate of every reference moment set, bit for bit with invert_batched and with invert per cell") {
  constexpr double moment_accuracy = 1e-9;
  std::size_t compared = 0, inaccurate = 0, with_rule = 0;
  const auto compare = [&]<int N>(std::integral_constant<int, N>, fluidbed_support support) {
    const MomentCells cells = reference_cells<N>();
    const std::size_t n = cells.sets.size();
    const moments::Support cpp_support =
        support == FLUIDBED_SUPPORT_REAL_LINE ? moments::Support::real_line : moments::Support::positive_half_line;
    const auto set_of = [&](std::size_t c) { return std::span<const double>(cells.sets[c].data(), 2 * N); };
    // A requirement that splits the cells with a rule: the median of their finite per-cell
    // estimates.
    std::vector<double> per_cell;
    for (std::size_t c = 0; c < n; ++c) {
      const auto r = moments::invert<double, N>(
          set_of(c), {.support = cpp_support, .estimate_error = true, .moment_accuracy = moment_accuracy});
      const double larger = std::max(r.error.nodes, r.error.weights);
      if (larger >= 0 && std::isfinite(larger)) per_cell.push_back(larger);
    }
    REQUIRE(!per_cell.empty());
    std::sort(per_cell.begin(), per_cell.end());
    const moments::InversionOptions options{.support = cpp_support, .estimate_error = true,
                                            .moment_accuracy = moment_accuracy,
                                            .required_accuracy = per_cell[per_cell.size() / 2]};
    Inverted c_out(N, n);
    REQUIRE(fluidbed_invert_moments_with_accuracy(N, support, n, cells.fields.data(), options.moment_accuracy,
                                                  options.required_accuracy, c_out.nodes.data(), c_out.weights.data(),
                                                  c_out.sizes.data(), c_out.status.data(), c_out.node_errors.data(),
                                                  c_out.weight_errors.data(), c_out.count_errors.data(),
                                                  nullptr) == FLUIDBED_OK);

    // The C++ batched inversion with the same options, bit for bit.
    moments::MomentBatch<double, N> batch;
    for (int k = 0; k < 2 * N; ++k) batch.moments[k] = std::span<const double>(cells.fields.data() + k * n, n);
    Inverted cpp(N, n);
    std::vector<moments::InversionStatus> cpp_status(n);
    moments::QuadratureBatch<double, N> out{.sizes = cpp.sizes,
                                            .status = cpp_status,
                                            .node_errors = cpp.node_errors,
                                            .weight_errors = cpp.weight_errors,
                                            .count_errors = cpp.count_errors};
    for (int i = 0; i < N; ++i) {
      out.nodes[i] = std::span<double>(cpp.nodes.data() + i * n, n);
      out.weights[i] = std::span<double>(cpp.weights.data() + i * n, n);
    }
    REQUIRE(moments::invert_batched(batch, out, options));
    for (std::size_t i = 0; i < N * n; ++i) {
      CHECK(same_bits(c_out.nodes[i], cpp.nodes[i]));
      CHECK(same_bits(c_out.weights[i], cpp.weights[i]));
    }
    for (std::size_t c = 0; c < n; ++c) {
      CHECK(c_out.sizes[c] == cpp.sizes[c]);
      CHECK(c_out.status[c] == static_cast<int>(cpp_status[c]));
      CHECK(same_bits(c_out.node_errors[c], cpp.node_errors[c]));
      CHECK(same_bits(c_out.weight_errors[c], cpp.weight_errors[c]));
      CHECK(same_bits(c_out.count_errors[c], cpp.count_errors[c]));
    }

    // invert per cell with the same options: the same estimate to the bit where the two paths
    // give the same rule (N <= 2; from N = 3 the rules agree to rounding), the same status where
    // the estimate is not within 2x of the requirement. −1 without a rule.
    for (std::size_t c = 0; c < n; ++c) {
      const auto r = moments::invert<double, N>(set_of(c), options);
      CHECK(has_rule(c_out.status[c]) == (r.error.nodes >= 0));
      if (!has_rule(c_out.status[c])) {
        CHECK(c_out.node_errors[c] == -1);
        CHECK(c_out.weight_errors[c] == -1);
        CHECK(c_out.count_errors[c] == -1);
      } else if (N <= 2) {
        CHECK(same_bits(c_out.node_errors[c], r.error.nodes));
        CHECK(same_bits(c_out.weight_errors[c], r.error.weights));
        CHECK(same_bits(c_out.count_errors[c], r.error.count));
        CHECK(c_out.status[c] == static_cast<int>(r.status));
      } else {
        const double near = std::max(r.error.nodes, r.error.weights) / options.required_accuracy;
        if (near < 0.5 || near > 2) CHECK(c_out.status[c] == static_cast<int>(r.status));
      }
      with_rule += has_rule(c_out.status[c]);
      inaccurate += c_out.status[c] == FLUIDBED_INVERSION_INACCURATE;
    }

    // The requirement changes statuses, never a rule: the rules of fluidbed_invert_moments, bit
    // for bit; and without error arrays the same statuses (the estimate made for them alone).
    Inverted plain(N, n), unstored(N, n);
    REQUIRE(fluidbed_invert_moments(N, support, n, cells.fields.data(), plain.nodes.data(), plain.weights.data(),
                                    plain.sizes.data(), plain.status.data(), nullptr) == FLUIDBED_OK);
    REQUIRE(fluidbed_invert_moments_with_accuracy(N, support, n, cells.fields.data(), options.moment_accuracy,
                                                  options.required_accuracy, unstored.nodes.data(),
                                                  unstored.weights.data(), unstored.sizes.data(),
                                                  unstored.status.data(), nullptr, nullptr, nullptr,
                                                  nullptr) == FLUIDBED_OK);
    for (std::size_t i = 0; i < N * n; ++i) {
      CHECK(same_bits(c_out.nodes[i], plain.nodes[i]));
      CHECK(same_bits(c_out.weights[i], plain.weights[i]));
    }
    CHECK(unstored.status == c_out.status);
    CHECK(unstored.sizes == plain.sizes);
    compared += n;
  };
  for_each_node_count(compare);
  CHECK(compared > 100);
  CHECK(inaccurate > with_rule / 4);
  CHECK(inaccurate < 3 * with_rule / 4);
  CHECK(std::string(moments::status_name(moments::InversionStatus(FLUIDBED_INVERSION_INACCURATE))) == "inaccurate");
}

namespace {

// The largest relative change of the nodes (relative to each node on [0, ∞), to the largest
// |node| on the real line) and of the weights of a two-node rule when each of its four moments
// is moved by ±delta relative, over all 16 sign patterns: long double inversions, the
// unperturbed rule the reference.
struct Shift {
  long double nodes = 0, weights = 0;
};
Shift worst_shift(const std::array<double, 4>& m, double delta, moments::Support support) {
  std::array<long double, 4> exact;
  std::copy(m.begin(), m.end(), exact.begin());
  const auto reference = moments::invert<long double, 2>(exact, {.support = support});
  REQUIRE(reference.status == moments::InversionStatus::ok);
  const auto& x = reference.quadrature.nodes;
  const auto& w = reference.quadrature.weights;
  const long double largest = std::max(std::abs(x[0]), std::abs(x[1]));
  Shift worst;
  for (unsigned pattern = 0; pattern < 16; ++pattern) {
    std::array<long double, 4> perturbed = exact;
    for (int k = 0; k < 4; ++k) perturbed[k] *= 1 + (pattern >> k & 1u ? delta : -delta);
    const auto moved = moments::invert<long double, 2>(perturbed, {.support = support});
    REQUIRE(moved.status == moments::InversionStatus::ok);
    for (int i = 0; i < 2; ++i) {
      const long double scale = support == moments::Support::positive_half_line ? std::abs(x[i]) : largest;
      worst.nodes = std::max(worst.nodes, std::abs(moved.quadrature.nodes[i] - x[i]) / scale);
      worst.weights = std::max(worst.weights, std::abs(moved.quadrature.weights[i] - w[i]) / w[i]);
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("C interface: the error estimate is the worst shift of the rule over the sign patterns of moment errors") {
  // Seed 003 Table 2 (mixed powder): M_0 … M_3 = 0.600, 116, 2.82e4, 7.84e6 µm^k, printed to three
  // digits; and a velocity distribution, atoms 0.4 and 0.6 at −1 and 2, on the real line.
  struct Case {
    std::array<double, 4> m;
    fluidbed_support support;
  };
  const Case cases[] = {{{0.600, 1.16e2, 2.82e4, 7.84e6}, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE},
                        {{1.0, 0.8, 2.8, 4.4}, FLUIDBED_SUPPORT_REAL_LINE}};
  for (const Case& c : cases)
    for (const double delta : {1e-3, 1e-7}) {
      std::array<double, 2> nodes, weights;
      int size = 0, status = -1;
      double node_error = 0, weight_error = 0;
      fluidbed_error error{};
      REQUIRE(fluidbed_invert_moments_with_accuracy(2, c.support, 1, c.m.data(), delta, 0, nodes.data(),
                                                    weights.data(), &size, &status, &node_error, &weight_error,
                                                    nullptr, &error) == FLUIDBED_OK);
      REQUIRE(status == FLUIDBED_INVERSION_OK);
      const Shift worst = worst_shift(
          c.m, delta, c.support == FLUIDBED_SUPPORT_REAL_LINE ? moments::Support::real_line
                                                              : moments::Support::positive_half_line);
      // Equal to first order, the second-order terms of the relative size of the shift itself
      // (measured on the real line at 1e-3: 0.13 % and 0.16 % of the estimate); for the powder at
      // 1e-3 the estimate is beyond first order (0.04) and made from the rules of the worst-case
      // sign pattern itself.
      CHECK(std::abs(double(worst.nodes) / node_error - 1) <= node_error);
      CHECK(std::abs(double(worst.weights) / weight_error - 1) <= weight_error);
    }
}

TEST_CASE("C interface: the accuracies out of their domain, NULL error arrays and the status inaccurate") {
  // One node: x = m_1/m_0 moves by up to 2δ relative, w = m_0 by δ (first order, exact), plus the
  // inversion's rounding, κ ε/√(2n) per moment with κ = 1/16 (accuracy.hpp): κ ε √2 and κ ε/√2.
  const double m[2] = {3.0, 1.5e-4}, delta = 1e-6, kappa_epsilon = std::numeric_limits<double>::epsilon() / 16;
  double node = 0, weight = 0, node_error = 0, weight_error = 0;
  int size = 0, status = -1;
  fluidbed_error error{};
  const auto invert = [&](double moment_accuracy, double required_accuracy, double* node_errors,
                          double* weight_errors) {
    return fluidbed_invert_moments_with_accuracy(1, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, 1, m, moment_accuracy,
                                                 required_accuracy, &node, &weight, &size, &status, node_errors,
                                                 weight_errors, nullptr, &error);
  };
  REQUIRE(invert(delta, 0, &node_error, &weight_error) == FLUIDBED_OK);
  CHECK(status == FLUIDBED_INVERSION_OK);
  CHECK(std::abs(node_error / (2 * delta + std::sqrt(2.0) * kappa_epsilon) - 1) < 1e-14);
  CHECK(std::abs(weight_error / (delta + kappa_epsilon / std::sqrt(2.0)) - 1) < 1e-14);
  const double rule_node = node, rule_weight = weight;

  // A requirement below the estimate: inaccurate, the rule still written; above it: ok. With
  // either error array alone, that one is written.
  node = weight = 0;
  REQUIRE(invert(delta, 1.5 * delta, nullptr, nullptr) == FLUIDBED_OK);
  CHECK(status == FLUIDBED_INVERSION_INACCURATE);
  CHECK(size == 1);
  CHECK((same_bits(node, rule_node) && same_bits(weight, rule_weight)));
  REQUIRE(invert(delta, 3 * delta, nullptr, nullptr) == FLUIDBED_OK);
  CHECK(status == FLUIDBED_INVERSION_OK);
  double alone = 0;
  REQUIRE(invert(delta, 0, &alone, nullptr) == FLUIDBED_OK);
  CHECK(same_bits(alone, node_error));
  REQUIRE(invert(delta, 0, nullptr, &alone) == FLUIDBED_OK);
  CHECK(same_bits(alone, weight_error));

  // Negative, NaN or infinite accuracies: a domain error naming the argument, nothing written.
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const double bad : {-1e-3, nan, inf}) {
    status = -1;
    node_error = 7;
    CHECK(invert(bad, 0, &node_error, &weight_error) == FLUIDBED_DOMAIN_ERROR);
    CHECK(std::string(error.message).find("'moment_accuracy'") != std::string::npos);
    CHECK(invert(0, bad, &node_error, &weight_error) == FLUIDBED_DOMAIN_ERROR);
    CHECK(std::string(error.message).find("'required_accuracy'") != std::string::npos);
    CHECK((status == -1 && node_error == 7));
  }
  CHECK(std::string(error.message) ==
        "fluidbed::moments::invert_batched: argument 'required_accuracy' = inf is out of domain (must be finite and "
        ">= 0)");
  CHECK(fluidbed_invert_moments_with_accuracy(1, FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, 1, m, 0, 0, &node, nullptr,
                                              &size, &status, nullptr, nullptr, nullptr,
                                              &error) == FLUIDBED_INVALID_ARGUMENT);
}


TEST_CASE("C interface: the elastic moduli on the elastic reference states bit for bit, at equilibrium and at a state") {
  const test::ReferenceTable table("elastic_state_reference.csv");
  std::size_t compared = 0;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const double rho_f = table.number(row, "fluid_density"), mu = table.number(row, "fluid_viscosity"),
                 rho_p = table.number(row, "particle_density"), d = table.number(row, "diameter"),
                 e = table.number(row, "voidage"), w = table.number(row, "slip"),
                 re_t = table.number(row, "reynolds"), g = 9.80665;
    for (const auto& model : elastic::ElasticModuli::all()) {
      const std::string name(elastic::ElasticModuli::name_of(model));
      CAPTURE(name);
      const Handle handle = create(name);
      double value = 0, d_voidage = 0, d_slip = 0;
      fluidbed_error error{};
      REQUIRE(fluidbed_elastic_modulus_at_equilibrium(handle.get(), 1, &e, &rho_f, &mu, &rho_p, &d, &re_t, &g, &value,
                                                      &d_voidage, &error) == FLUIDBED_OK);
      const elastic::EquilibriumState<double> equilibrium{e, {rho_f, mu}, {rho_p, d}, re_t, g};
      std::visit(
          [&]<class Model>(const Model& m) {
            CHECK(same_bits(value, m.checked(equilibrium)));
            CHECK(same_bits(d_voidage, m.checked_with_derivatives(equilibrium).d_voidage));
            const fluidbed_status at_state = fluidbed_elastic_modulus_at_state(
                handle.get(), 1, &e, &w, &rho_f, &mu, &d, &value, &d_voidage, &d_slip, &error);
            if constexpr (elastic::DefinedOffEquilibrium<Model, double>) {
              REQUIRE(at_state == FLUIDBED_OK);
              const drag::DragState<double> state{e, w, {rho_f, mu}, d};
              const auto with = m.checked_with_derivatives(state);
              CHECK(same_bits(value, m.checked(state)));
              CHECK(same_bits(d_voidage, with.d_voidage));
              CHECK(same_bits(d_slip, with.d_slip));
            } else {
              CHECK(at_state == FLUIDBED_INVALID_ARGUMENT);
              CHECK(std::string(error.message).ends_with("defines no modulus off equilibrium"));
            }
          },
          model);
      ++compared;
    }
  }
  CHECK(compared == 3 * table.size());
}

namespace {

// The mixture radial distribution the mixture table names (lebowitz, mansoori, modified_mansoori).
std::string mixture_name(const std::string& table_name) {
  if (table_name == "lebowitz") return "Lebowitz";
  if (table_name == "mansoori") return "Mansoori";
  REQUIRE(table_name == "modified_mansoori");
  return "ModifiedMansoori";
}

}  // namespace

TEST_CASE("C interface: the mixture radial distributions and the solid-solid drag on every mixture reference row, bit for bit") {
  const test::ReferenceTable table("ktgf_mixture_reference.csv");
  struct Cells {
    std::size_t classes = 0, i = 0, k = 0;
    std::vector<std::size_t> rows;
  };
  std::map<std::string, Cells> groups;  // the rows one call evaluates: same closure, parameters, classes and pair
  for (std::size_t row = 0; row < table.size(); ++row) {
    Cells& g = groups[table.text(row, "function") + "|" + table.text(row, "variant") + "|" +
                                 table.text(row, "classes") + "|" + table.text(row, "i") + "|" +
                                 table.text(row, "k") + "|" + table.text(row, "max_packing") + "|" +
                                 table.text(row, "friction_coefficient") + "|" + table.text(row, "restitution")];
    g.classes = static_cast<std::size_t>(table.number(row, "classes"));
    g.i = static_cast<std::size_t>(table.number(row, "i"));
    g.k = static_cast<std::size_t>(table.number(row, "k"));
    g.rows.push_back(row);
  }
  std::size_t rdf_rows = 0, drag_rows = 0;
  for (const auto& group : groups) {  // no structured binding: clang 14 cannot capture one
    const std::string& key = group.first;
    const Cells& g = group.second;
    INFO(key);
    const std::size_t first = g.rows.front(), n = g.rows.size(), classes = g.classes;
    const auto [author, rdf_table_name] = test::split_variant(table.text(first, "variant"));
    const bool drag = table.text(first, "function") == "solid_solid_drag";
    const std::string rdf_name = mixture_name(drag ? rdf_table_name : author);
    const Handle rdf = create(rdf_name);
    const double max_packing = table.number(first, "max_packing");
    if (rdf_name == "ModifiedMansoori") REQUIRE(fluidbed_closure_set_parameter(rdf.get(), "max_packing", max_packing, nullptr) == FLUIDBED_OK);
    std::vector<double> fractions(classes * n), diameters(classes * n), g_ik(n), d_fractions(classes * n);
    for (std::size_t c = 0; c < n; ++c)
      for (std::size_t m = 0; m < classes; ++m) {
        fractions[m * n + c] = table.number(g.rows[c], "phi" + std::to_string(m + 1));
        diameters[m * n + c] = table.number(g.rows[c], "d" + std::to_string(m + 1));
      }
    REQUIRE(fluidbed_mixture_radial_distribution(rdf.get(), n, classes, g.i, g.k, fractions.data(), diameters.data(),
                                                 g_ik.data(), d_fractions.data(), nullptr) == FLUIDBED_OK);
    // The C++ checked calls, cell by cell (the derivatives from checked_with_derivatives of 3 classes
    // at most, the table's).
    const auto cpp = [&](auto law, std::size_t c) {
      std::array<double, 3> phi{}, d{};
      for (std::size_t m = 0; m < classes; ++m) phi[m] = fractions[m * n + c], d[m] = diameters[m * n + c];
      const std::span<const double> ds(d.data(), classes);
      const double value = law.checked(std::span<const double>(phi.data(), classes), ds, g.i, g.k);
      const auto with = [&]<std::size_t N>(std::integral_constant<std::size_t, N>) {
        std::array<double, N> p{};
        std::copy_n(phi.begin(), N, p.begin());
        const auto r = law.checked_with_derivatives(p, ds, g.i, g.k);
        return std::vector<double>(r.d_fractions.begin(), r.d_fractions.end());
      };
      const std::vector<double> slopes = classes == 1   ? with(std::integral_constant<std::size_t, 1>{})
                                         : classes == 2 ? with(std::integral_constant<std::size_t, 2>{})
                                                        : with(std::integral_constant<std::size_t, 3>{});
      CHECK(same_bits(g_ik[c], value));
      for (std::size_t m = 0; m < classes; ++m) CHECK(same_bits(d_fractions[m * n + c], slopes[m]));
    };
    for (std::size_t c = 0; c < n; ++c) {
      if (rdf_name == "Lebowitz") cpp(kinetic_theory::Lebowitz{}, c);
      else if (rdf_name == "Mansoori") cpp(kinetic_theory::Mansoori{}, c);
      else cpp(kinetic_theory::ModifiedMansoori{max_packing}, c);
    }
    if (!drag) {
      for (std::size_t c = 0; c < n; ++c)  // and the table's independent values
        CHECK(test::relative_difference(g_ik[c], table.number(g.rows[c], "value")) < 1e-13);
      rdf_rows += n;
      continue;
    }
    // K_ik of the row's pair with g_ik from the C call.
    const Handle law = create("SyamlalSolidSolidDrag");
    const double friction = table.number(first, "friction_coefficient"), e = table.number(first, "restitution");
    REQUIRE(fluidbed_closure_set_parameter(law.get(), "friction_coefficient", friction, nullptr) == FLUIDBED_OK);
    std::vector<double> phi_p(n), phi_q(n), rho_p(n), d_p(n), rho_q(n), d_q(n), restitution(n, e), speed(n), k_pq(n),
        d_phi_p(n), d_phi_q(n), d_g(n), d_speed(n);
    for (std::size_t c = 0; c < n; ++c) {
      phi_p[c] = fractions[g.i * n + c], phi_q[c] = fractions[g.k * n + c];
      d_p[c] = diameters[g.i * n + c], d_q[c] = diameters[g.k * n + c];
      rho_p[c] = table.number(g.rows[c], "rho_i"), rho_q[c] = table.number(g.rows[c], "rho_k");
      speed[c] = table.number(g.rows[c], "relative_speed");
    }
    REQUIRE(fluidbed_solid_solid_drag(law.get(), n, phi_p.data(), phi_q.data(), rho_p.data(), d_p.data(), rho_q.data(),
                                      d_q.data(), restitution.data(), g_ik.data(), speed.data(), k_pq.data(),
                                      d_phi_p.data(), d_phi_q.data(), d_g.data(), d_speed.data(),
                                      nullptr) == FLUIDBED_OK);
    const kinetic_theory::SyamlalSolidSolidDrag cpp_law{friction};
    for (std::size_t c = 0; c < n; ++c) {
      const Particles<double> p{rho_p[c], d_p[c]}, q{rho_q[c], d_q[c]};
      CHECK(same_bits(k_pq[c], cpp_law.checked(phi_p[c], phi_q[c], p, q, e, g_ik[c], speed[c])));
      const auto d = cpp_law.checked_with_derivatives(phi_p[c], phi_q[c], p, q, e, g_ik[c], speed[c]);
      CHECK(same_bits(d_phi_p[c], d.d_phi_p));
      CHECK(same_bits(d_phi_q[c], d.d_phi_q));
      CHECK(same_bits(d_g[c], d.d_contact_rdf));
      CHECK(same_bits(d_speed[c], d.d_relative_speed));
      CHECK(test::relative_difference(k_pq[c], table.number(g.rows[c], "value")) < 1e-13);
    }
    drag_rows += n;
  }
  CHECK(rdf_rows + drag_rows == table.size());
  CHECK(drag_rows >= 200);
}

TEST_CASE("C interface: the gas exchange sources on every source row of the exchange reference table, bit for bit") {
  const test::ReferenceTable table("ktgf_exchange_reference.csv");
  std::map<std::string, std::vector<std::size_t>> groups;  // by variant
  for (std::size_t row = 0; row < table.size(); ++row)
    if (table.text(row, "function") == "fluctuating_energy_source") groups[table.text(row, "variant")].push_back(row);
  REQUIRE(groups.size() == 3);
  std::size_t compared = 0;
  for (const auto& group : groups) {  // no structured binding: clang 14 cannot capture one
    const std::string& variant = group.first;
    const std::vector<std::size_t>& rows = group.second;
    INFO(variant);
    const auto [author, rdf_table_name] = test::split_variant(variant);
    const bool koch_sangani = author == "koch_sangani";
    const Handle law = create(koch_sangani ? "KochSanganiSource" : "DragFluctuationSource");
    const Handle rdf = create(koch_sangani ? test::library_name(test::radial_distribution_names, rdf_table_name)
                                           : "CarnahanStarling");
    if (rdf_table_name == "ogawa")  // the tables' Ogawa: φ_max = 0.63
      REQUIRE(fluidbed_closure_set_parameter(rdf.get(), "max_packing", 0.63, nullptr) == FLUIDBED_OK);
    const std::size_t n = rows.size();
    const auto column = [&](const char* name) {
      std::vector<double> v(n);
      for (std::size_t c = 0; c < n; ++c) v[c] = table.number(rows[c], name);
      return v;
    };
    const std::vector<double> phi = column("solid_fraction"), theta = column("granular_temperature"),
                              slip = column("slip"), beta = column("beta"), mu = column("gas_viscosity"),
                              d = column("diameter"), rho = column("particle_density"), e = column("restitution");
    std::vector<double> source(n), d_phi(n), d_theta(n), d_beta(n), d_slip(n);
    // Each source reads only its own arguments: the other's are NULL.
    REQUIRE(fluidbed_gas_exchange_source(law.get(), koch_sangani ? rdf.get() : nullptr, n, phi.data(), theta.data(),
                                         slip.data(), koch_sangani ? nullptr : beta.data(),
                                         koch_sangani ? mu.data() : nullptr, d.data(), rho.data(), e.data(),
                                         source.data(), d_phi.data(), d_theta.data(), d_beta.data(), d_slip.data(),
                                         nullptr) == FLUIDBED_OK);
    for (std::size_t c = 0; c < n; ++c) {
      const kinetic_theory::GranularMaterial<double> m{d[c], rho[c], e[c]};
      kinetic_theory::GasExchangeDerivatives<double> expected{};
      if (koch_sangani) {
        const auto check_with = [&](const auto& g0) {
          CHECK(same_bits(source[c], kinetic_theory::KochSanganiSource{}.checked(phi[c], theta[c], g0.checked(phi[c]),
                                                                                 slip[c], mu[c], m)));
          expected = kinetic_theory::KochSanganiSource{}.checked_with_derivatives(phi[c], theta[c], g0, slip[c], mu[c], m);
        };
        if (rdf_table_name == "ogawa") check_with(kinetic_theory::Ogawa{0.63});
        else check_with(kinetic_theory::CarnahanStarling{});
      } else {
        const kinetic_theory::DragFluctuationSource s;
        CHECK(same_bits(source[c], s.checked(phi[c], theta[c], beta[c], slip[c], m)));
        expected = s.checked_with_derivatives(phi[c], theta[c], beta[c], slip[c], m);
      }
      CHECK(same_bits(d_phi[c], expected.d_solid_fraction));
      CHECK(same_bits(d_theta[c], expected.d_granular_temperature));
      CHECK(same_bits(d_beta[c], expected.d_beta));
      CHECK(same_bits(d_slip[c], expected.d_slip));
      CHECK(test::relative_difference(source[c], table.number(rows[c], "value")) < 1e-13);
    }
    compared += n;
  }
  CHECK(compared == 72);
}

TEST_CASE("C interface: realizability and correction of the moments reference sets and corrupted copies, bit for bit") {
  const auto sets = test::MomentReference::instance().moment_sets();  // the moments of each case
  // Each set, and copies with one moment k >= 1 multiplied by 1.3 or 0.6 (advection's corruption).
  std::vector<std::vector<double>> all;
  for (const auto& [name, m] : sets) {
    all.push_back(m);
    for (std::size_t k = 1; k < m.size(); ++k)
      for (const double factor : {1.3, 0.6}) {
        all.push_back(m);
        all.back()[k] *= factor;
      }
  }
  std::map<int, int> correction_statuses;
  std::size_t compared = 0;
  const auto compare = [&]<int N>(std::integral_constant<int, N>) {
    for (const int count : {2 * N - 1, 2 * N}) {
      std::vector<std::vector<double>> cells;
      for (const auto& m : all)
        if (m.size() >= std::size_t(count)) cells.emplace_back(m.begin(), m.begin() + count);
      const std::size_t n = cells.size();
      std::vector<double> in(count * n), failing(n), corrected(count * n);
      std::vector<int> status(n), realizable(n), first_failing(n), corrected_status(n), corrected_realizable(n);
      for (std::size_t c = 0; c < n; ++c)
        for (int k = 0; k < count; ++k) in[k * n + c] = cells[c][k];
      for (const fluidbed_support support : {FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, FLUIDBED_SUPPORT_REAL_LINE}) {
        REQUIRE(fluidbed_moment_realizability(support, count, n, in.data(), status.data(), realizable.data(),
                                              first_failing.data(), failing.data(), nullptr) == FLUIDBED_OK);
        for (std::size_t c = 0; c < n; ++c) {
          const auto r = moments::realizability<double, N>(
              std::span<const double>(cells[c]),
              support == FLUIDBED_SUPPORT_REAL_LINE ? moments::Support::real_line : moments::Support::positive_half_line);
          CHECK(status[c] == int(r.status));
          CHECK(realizable[c] == r.realizable_moments);
          CHECK(first_failing[c] == r.first_failing_index);
          CHECK(same_bits(failing[c], r.failing_value));
        }
      }
      REQUIRE(fluidbed_correct_moments(count, n, in.data(), nullptr, corrected.data(), corrected_status.data(),
                                       corrected_realizable.data(), nullptr) == FLUIDBED_OK);
      for (std::size_t c = 0; c < n; ++c) {
        const auto r = moments::correct_moments<double, N>(std::span<const double>(cells[c]));
        CHECK(corrected_status[c] == int(r.status));
        CHECK(corrected_realizable[c] == r.realizable_moments);
        for (int k = 0; k < count; ++k) CHECK(same_bits(corrected[k * n + c], r.moments[k]));
        ++correction_statuses[corrected_status[c]];
      }
      // In place, with options: the same as the C++ call with those options.
      const fluidbed_correction_options options{3, 5, 1e-9};
      std::vector<double> in_place = in;
      REQUIRE(fluidbed_correct_moments(count, n, in_place.data(), &options, in_place.data(), corrected_status.data(),
                                       nullptr, nullptr) == FLUIDBED_OK);
      for (std::size_t c = 0; c < n; ++c) {
        const auto r = moments::correct_moments<double, N>(std::span<const double>(cells[c]), {3, 5, 1e-9});
        CHECK(corrected_status[c] == int(r.status));
        for (int k = 0; k < count; ++k) CHECK(same_bits(in_place[k * n + c], r.moments[k]));
      }
      compared += n;
    }
  };
  for_each_node_count(compare);
  CHECK(compared > 1000);
  // The corrupted copies reach every correction but the empty cell's and the failure's.
  for (const auto status : {FLUIDBED_CORRECTION_UNCHANGED, FLUIDBED_CORRECTION_MCGRAW, FLUIDBED_CORRECTION_LOGNORMAL,
                            FLUIDBED_CORRECTION_MONODISPERSE})
    CHECK(correction_statuses[status] > 0);
  const fluidbed_correction_options defaults = fluidbed_correction_default_options();
  CHECK(defaults.protected_moments == 1);
  CHECK(defaults.max_iterations == 20);
  CHECK(defaults.degenerate_tolerance == std::cbrt(std::numeric_limits<double>::epsilon()));
}

TEST_CASE("C interface: bad input to the mixture, exchange and moment functions") {
  fluidbed_error error{};
  const Handle lebowitz = create("Lebowitz");
  const double fractions[] = {0.2, 0.3, std::numeric_limits<double>::quiet_NaN(), 0.1};  // 2 cells, 2 classes
  const double diameters[] = {1e-4, 1e-4, 2e-4, 2e-4};
  double g[2] = {-1, -1}, slopes[4];
  CHECK(fluidbed_mixture_radial_distribution(lebowitz.get(), 2, 2, 0, 1, fractions, diameters, g, slopes, &error) ==
        FLUIDBED_DOMAIN_ERROR);
  CHECK(error.index == 0);  // class 1 of cell 0 is NaN
  CHECK(std::string(error.message).find("fractions[1]") != std::string::npos);
  CHECK(g[0] == -1);
  CHECK(fluidbed_mixture_radial_distribution(lebowitz.get(), 2, 2, 0, 2, diameters, diameters, g, nullptr, &error) ==
        FLUIDBED_DOMAIN_ERROR);  // k beyond the classes: the checked API's error
  CHECK(std::string(error.message).find("'k' = 2") != std::string::npos);
  for (const std::size_t classes : {std::size_t(0), std::size_t(FLUIDBED_MAX_CLASSES + 1)}) {
    CHECK(fluidbed_mixture_radial_distribution(lebowitz.get(), 1, classes, 0, 0, diameters, diameters, g, nullptr,
                                               &error) == FLUIDBED_INVALID_ARGUMENT);
    CHECK(std::string(error.message).ends_with("classes; 1 to 10 are offered"));
  }
  const Handle source = create("KochSanganiSource"), drag_source = create("DragFluctuationSource"),
               carnahan = create("CarnahanStarling");
  const double one[] = {0.3}, theta[] = {1e-3}, negative[] = {-1.0}, d[] = {3e-4}, rho[] = {2500}, e[] = {0.9};
  double out[1];
  // Koch-Sangani needs its radial distribution and the gas viscosity, the drag-based source β.
  CHECK(fluidbed_gas_exchange_source(source.get(), nullptr, 1, one, theta, one, nullptr, one, d, rho, e, out, nullptr,
                                     nullptr, nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(fluidbed_gas_exchange_source(source.get(), carnahan.get(), 1, one, theta, one, nullptr, nullptr, d, rho, e, out,
                                     nullptr, nullptr, nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(fluidbed_gas_exchange_source(drag_source.get(), nullptr, 1, one, theta, one, nullptr, nullptr, d, rho, e, out,
                                     nullptr, nullptr, nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(fluidbed_gas_exchange_source(drag_source.get(), nullptr, 1, one, theta, negative, one, nullptr, d, rho, e, out,
                                     nullptr, nullptr, nullptr, nullptr, &error) == FLUIDBED_DOMAIN_ERROR);
  CHECK(std::string(error.message).find("slip") != std::string::npos);
  CHECK(fluidbed_gas_exchange_source(lebowitz.get(), nullptr, 1, one, theta, one, one, one, d, rho, e, out, nullptr,
                                     nullptr, nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(std::string(error.message) == "fluidbed: gas_exchange_source: Lebowitz is not a gas exchange source");
  const Handle syamlal = create("SyamlalSolidSolidDrag");
  CHECK(fluidbed_solid_solid_drag(syamlal.get(), 1, one, one, rho, d, rho, d, e, negative, one, out, nullptr, nullptr,
                                  nullptr, nullptr, &error) == FLUIDBED_DOMAIN_ERROR);
  CHECK(std::string(error.message).find("contact_rdf") != std::string::npos);
  // Moment counts outside 1 … 16 and options outside their domain are errors; cells are statuses.
  const double m[] = {1.0, 2.0};
  int status[1], realizable[1];
  double corrected[2];
  for (const int count : {0, 17}) {
    CHECK(fluidbed_moment_realizability(FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, count, 1, m, status, realizable, nullptr,
                                        nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
    CHECK(fluidbed_correct_moments(count, 1, m, nullptr, corrected, status, nullptr, &error) ==
          FLUIDBED_INVALID_ARGUMENT);
  }
  CHECK(fluidbed_moment_realizability(static_cast<fluidbed_support>(2), 2, 1, m, status, realizable, nullptr, nullptr,
                                      &error) == FLUIDBED_INVALID_ARGUMENT);
  const fluidbed_correction_options bad[] = {{0, 20, 1e-6}, {1, -1, 1e-6}, {1, 20, -1.0},
                                             {1, 20, std::numeric_limits<double>::quiet_NaN()}};
  for (const auto& options : bad) {
    CHECK(fluidbed_correct_moments(2, 1, m, &options, corrected, status, nullptr, &error) == FLUIDBED_DOMAIN_ERROR);
    CHECK(std::string(error.message).starts_with("fluidbed::moments::correct_moments: argument '"));
  }
  const double nan_set[] = {1.0, std::numeric_limits<double>::quiet_NaN()};
  CHECK(fluidbed_correct_moments(1, 2, nan_set, nullptr, corrected, status, nullptr, &error) == FLUIDBED_OK);
  CHECK(fluidbed_moment_realizability(FLUIDBED_SUPPORT_POSITIVE_HALF_LINE, 2, 1, nan_set, status, realizable, nullptr,
                                      nullptr, &error) == FLUIDBED_OK);
  CHECK(status[0] == FLUIDBED_INVERSION_INVALID_INPUT);
}

TEST_CASE("C interface: DQMOM sources, moment and point-functional forms, bit for bit with the C++ solves") {
  namespace dq = fluidbed::moments::dqmom;
  constexpr std::size_t n = 37;  // not a multiple of the lanes
  const auto compare = [&]<int N>(std::integral_constant<int, N>) {
    constexpr int count = N;
    INFO(count << " nodes");
    const std::size_t nodes_size = std::size_t(count) * n, moments_size = 2 * nodes_size;
    std::vector<double> nodes(nodes_size), weights(nodes_size), rates(nodes_size), intensity(nodes_size),
        sources(moments_size);
    for (std::size_t c = 0; c < n; ++c) {
      for (int i = 0; i < count; ++i) {
        const std::size_t at = std::size_t(i) * n + c;
        nodes[at] = 40e-6 * std::pow(1.6, i) * (1 + 0.01 * double(c));  // distinct, SI
        weights[at] = 0.05 + 0.01 * double((i + c) % 7);
        rates[at] = 1e-7 * (i % 2 ? -1.0 : 1.0) * (1 + 0.1 * double(c % 5));
        intensity[at] = 1e-14 * double(1 + (i + 2 * c) % 3);
      }
      for (int k = 0; k < 2 * count; ++k) sources[std::size_t(k) * n + c] = std::pow(-2e-4, k) * double(1 + c % 4);
    }
    nodes[1] = nodes[(count > 1 ? n : 0) + 1] * (count > 1 ? 1 + 1e-9 : 1);  // a cell with merged nodes
    nodes[2] = -nodes[2];                                                   // an invalid cell
    std::vector<double> a(nodes_size), b(nodes_size), condition(n), a2(nodes_size), b2(nodes_size), condition2(n);
    std::vector<int> status(n), status2(n);
    fluidbed_error error{};
    REQUIRE(fluidbed_dqmom_sources(count, n, nodes.data(), weights.data(), sources.data(), a.data(), b.data(),
                                   status.data(), condition.data(), &error) == FLUIDBED_OK);
    REQUIRE(fluidbed_dqmom_growth_diffusion_sources(count, FLUIDBED_DQMOM_VOLUME_FRACTION, n, nodes.data(),
                                                    weights.data(), rates.data(), intensity.data(), a2.data(),
                                                    b2.data(), status2.data(), condition2.data(), &error) == FLUIDBED_OK);
    CHECK(status[2] == FLUIDBED_DQMOM_INVALID_INPUT);
    if (count > 1) CHECK(status[1] == FLUIDBED_DQMOM_MERGED_NODES);
    {
      // The C++ batched solve on the same fields.
      std::array<std::vector<double>, N> ca, cb;
      std::vector<dq::SourceStatus> cs(n);
      std::vector<double> ck(n);
      dq::SourceBatch<double, N> batch;
      for (int i = 0; i < N; ++i) {
        ca[i].resize(n), cb[i].resize(n);
        batch.nodes[i] = std::span<const double>(nodes.data() + std::size_t(i) * n, n);
        batch.weights[i] = std::span<const double>(weights.data() + std::size_t(i) * n, n);
        batch.weight_sources[i] = ca[i], batch.weighted_node_sources[i] = cb[i];
      }
      for (int k = 0; k < 2 * N; ++k) batch.moment_sources[k] = std::span<const double>(sources.data() + std::size_t(k) * n, n);
      batch.status = cs, batch.condition = ck;
      dq::solve_batched(batch);
      for (std::size_t c = 0; c < n; ++c) {
        INFO("cell " << c);
        CHECK(status[c] == int(cs[c]));
        CHECK(same_bits(condition[c], ck[c]));
        // The per-cell System with growth and diffusion as point functionals.
        std::array<double, N> x{}, w{}, g{}, d{};
        for (int i = 0; i < N; ++i) {
          const std::size_t at = std::size_t(i) * n + c;
          x[i] = nodes[at], w[i] = weights[at], g[i] = rates[at], d[i] = intensity[at];
          CHECK(same_bits(a[at], ca[i][c]));
          CHECK(same_bits(b[at], cb[i][c]));
        }
        const dq::System<double, N> system{std::span<const double>(x), std::span<const double>(w)};
        const auto growth = dq::growth_terms<double, N>(dq::Weights::volume_fraction, std::span<const double>(w),
                                                        std::span<const double>(x), std::span<const double>(g));
        const auto diffusion = dq::diffusion_terms<double, N>(std::span<const double>(x), std::span<const double>(d));
        std::array<dq::PointSource<double>, 3 * N> terms{};
        std::copy(growth.begin(), growth.end(), terms.begin());
        std::copy(diffusion.begin(), diffusion.end(), terms.begin() + 2 * N);
        const auto out = system.solve(std::span<const dq::PointSource<double>>(terms));
        CHECK(status2[c] == int(out.status));
        CHECK(same_bits(condition2[c], out.condition));
        for (int i = 0; i < N; ++i) {
          CHECK(same_bits(a2[std::size_t(i) * n + c], out.weight[i]));
          CHECK(same_bits(b2[std::size_t(i) * n + c], out.weighted_node[i]));
        }
      }
    }
  };
  [&]<int... M>(std::integer_sequence<int, M...>) {
    (compare(std::integral_constant<int, M + 1>{}), ...);
  }(std::make_integer_sequence<int, FLUIDBED_MAX_NODES>{});
  // Counts, arrays and the weights kind are errors; a bad cell is a status.
  const double x[] = {1e-4, 2e-4}, w[] = {0.1, 0.2}, s[] = {1, 1, 1, 1};
  double a[2], b[2];
  int status[1];
  fluidbed_error error{};
  for (const int count : {0, FLUIDBED_MAX_NODES + 1})
    CHECK(fluidbed_dqmom_sources(count, 1, x, w, s, a, b, status, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(fluidbed_dqmom_sources(2, 1, x, nullptr, s, a, b, status, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(fluidbed_dqmom_growth_diffusion_sources(2, static_cast<fluidbed_dqmom_weights>(2), 1, x, w, nullptr, nullptr, a,
                                                b, status, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(std::string(error.message) == "fluidbed: unknown fluidbed_dqmom_weights 2");
  // Neither growth nor diffusion: no sources.
  REQUIRE(fluidbed_dqmom_growth_diffusion_sources(2, FLUIDBED_DQMOM_NUMBER_DENSITY, 1, x, w, nullptr, nullptr, a, b,
                                                  status, nullptr, &error) == FLUIDBED_OK);
  CHECK(status[0] == FLUIDBED_DQMOM_OK);
  CHECK(a[0] == 0);
  CHECK(b[1] == 0);
}

TEST_CASE("C interface: the unequal-temperature mixture, 1 to 4 classes, each mixture radial distribution, values and derivatives bit for bit") {
  constexpr std::size_t n = 7;  // cells
  // The C++ quantities in the C layout: quantity q's entry e (i, or i N + k) of a cell.
  const auto entries_of = []<class V, std::size_t N>(const kinetic_theory::ClassKineticValues<V, N>& v) {
    std::array<std::vector<V>, 8> q;
    for (std::size_t i = 0; i < N; ++i) {
      q[0].push_back(v.pressure[i]);
      q[4].push_back(v.dissipation[i]);
      for (std::size_t k = 0; k < N; ++k) {
        q[1].push_back(v.shear_viscosity[i][k]);
        q[2].push_back(v.bulk_viscosity[i][k]);
        q[3].push_back(v.conductivity[i][k]);
        q[5].push_back(v.drag[i][k]);
        q[6].push_back(v.segregation[i][k]);
        q[7].push_back(v.radial_distribution[i][k]);
      }
    }
    return q;
  };
  const auto compare = [&]<std::size_t N>(std::integral_constant<std::size_t, N>) {
    for (const auto& law : kinetic_theory::MixtureRadialDistributions::all()) {
      const std::string name(kinetic_theory::MixtureRadialDistributions::name_of(law));
      INFO(N << " classes, " << name);
      const Handle radial = create(name);
      std::vector<double> fractions(N * n), temperatures(N * n), diameters(N * n), densities(N * n), restitution(n);
      std::vector<kinetic_theory::GranularClassesState<double, N>> states(n);
      for (std::size_t c = 0; c < n; ++c) {
        auto& s = states[c];
        for (std::size_t m = 0; m < N; ++m) {
          s.fractions[m] = (0.05 + 0.45 * double(c) / double(n)) / double(N) * (1 + 0.2 * double(m));  // Σ α < 0.57
          s.temperatures[m] = 1e-3 * (1 + double((c + 2 * m) % 5)) * (m == 1 ? 3 : 1);
          s.diameters[m] = 1e-4 * (1 + 0.7 * double(m));
          s.densities[m] = 2500 - 400 * double(m);
          fractions[m * n + c] = s.fractions[m], temperatures[m * n + c] = s.temperatures[m];
          diameters[m * n + c] = s.diameters[m], densities[m * n + c] = s.densities[m];
        }
        s.restitution = restitution[c] = 0.7 + 0.3 * double(c) / double(n - 1);  // e = 1 in the last cell
      }
      const std::array<std::size_t, 8> sizes{N * n, N * N * n, N * N * n, N * N * n, N * n, N * N * n, N * N * n,
                                             N * N * n};
      std::array<std::vector<double>, 8> values, plain, by_fraction, by_temperature;
      for (std::size_t q = 0; q < 8; ++q) {
        values[q].assign(sizes[q], -1), plain[q].assign(sizes[q], -1);
        by_fraction[q].assign(N * sizes[q], -1), by_temperature[q].assign(N * sizes[q], -1);
      }
      fluidbed_error error{};
      REQUIRE_MESSAGE(fluidbed_unequal_temperature_mixture(
                          radial.get(), n, N, fractions.data(), temperatures.data(), diameters.data(), densities.data(),
                          restitution.data(), plain[0].data(), plain[1].data(), plain[2].data(), plain[3].data(),
                          plain[4].data(), plain[5].data(), plain[6].data(), plain[7].data(), &error) == FLUIDBED_OK,
                      error.message);
      std::array<double*, 24> out{};
      for (std::size_t q = 0; q < 8; ++q)
        out[3 * q] = values[q].data(), out[3 * q + 1] = by_fraction[q].data(), out[3 * q + 2] = by_temperature[q].data();
      REQUIRE_MESSAGE(fluidbed_unequal_temperature_mixture_with_derivatives(
                          radial.get(), n, N, fractions.data(), temperatures.data(), diameters.data(), densities.data(),
                          restitution.data(), out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8],
                          out[9], out[10], out[11], out[12], out[13], out[14], out[15], out[16], out[17], out[18],
                          out[19], out[20], out[21], out[22], out[23], &error) == FLUIDBED_OK,
                      error.message);
      std::size_t compared = 0;
      std::visit(
          [&](const auto& rdf) {
            const kinetic_theory::UnequalTemperatureMixture mixture{rdf};
            for (std::size_t c = 0; c < n; ++c) {
              INFO("cell " << c);
              const auto value = entries_of(mixture.checked(states[c]));
              const auto with = entries_of(mixture.checked_with_derivatives(states[c]));
              for (std::size_t q = 0; q < 8; ++q)
                for (std::size_t e = 0; e < value[q].size(); ++e) {
                  INFO("quantity " << q << ", entry " << e);
                  CHECK(same_bits(values[q][e * n + c], value[q][e]));
                  CHECK(same_bits(plain[q][e * n + c], value[q][e]));
                  for (std::size_t m = 0; m < N; ++m) {
                    CHECK(same_bits(by_fraction[q][m * sizes[q] + e * n + c], with[q][e].d_fractions[m]));
                    CHECK(same_bits(by_temperature[q][m * sizes[q] + e * n + c], with[q][e].d_temperatures[m]));
                  }
                  ++compared;
                }
            }
          },
          law);
      CHECK(compared == n * (2 * N + 6 * N * N));
      // Outputs not wanted are NULL: what is asked for is written alone, the same bits.
      std::vector<double> pressure(N * n), d_pressure(N * N * n);
      REQUIRE(fluidbed_unequal_temperature_mixture_with_derivatives(
                  radial.get(), n, N, fractions.data(), temperatures.data(), diameters.data(), densities.data(),
                  restitution.data(), pressure.data(), nullptr, d_pressure.data(), nullptr, nullptr, nullptr, nullptr,
                  nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                  nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, &error) == FLUIDBED_OK);
      CHECK(std::equal(pressure.begin(), pressure.end(), values[0].begin(), same_bits<double>));
      CHECK(std::equal(d_pressure.begin(), d_pressure.end(), by_temperature[0].begin(), same_bits<double>));
    }
  };
  [&]<std::size_t... M>(std::index_sequence<M...>) {
    (compare(std::integral_constant<std::size_t, M + 1>{}), ...);
  }(std::make_index_sequence<4>{});
}

TEST_CASE("C interface: bad input to the unequal-temperature mixture gives the checked API's error and the cell") {
  const Handle radial = create("ModifiedMansoori");
  // 3 cells of 2 classes; cell 1's class 1 is cold (Θ = 0), outside the theory's domain.
  const double fractions[] = {0.2, 0.2, 0.2, 0.1, 0.1, 0.1}, temperatures[] = {1e-3, 1e-3, 1e-3, 2e-3, 0, 2e-3},
               diameters[] = {1e-4, 1e-4, 1e-4, 2e-4, 2e-4, 2e-4}, densities[] = {2500, 2500, 2500, 1500, 1500, 1500},
               restitution[] = {0.9, 0.9, 0.9};
  std::array<double, 6> pressure;
  pressure.fill(-1);
  fluidbed_error error{};
  CHECK(fluidbed_unequal_temperature_mixture(radial.get(), 3, 2, fractions, temperatures, diameters, densities,
                                             restitution, pressure.data(), nullptr, nullptr, nullptr, nullptr, nullptr,
                                             nullptr, nullptr, &error) == FLUIDBED_DOMAIN_ERROR);
  CHECK(error.status == FLUIDBED_DOMAIN_ERROR);
  CHECK(error.index == 1);
  CHECK(pressure[0] != -1);  // written below the failing cell only
  CHECK(pressure[1] == -1);
  CHECK(pressure[2] == -1);
  // The message is the C++ checked call's.
  const kinetic_theory::GranularClassesState<double, 2> cold{{0.2, 0.1}, {1e-3, 0}, {1e-4, 2e-4}, {2500, 1500}, 0.9};
  std::string expected;
  try {
    static_cast<void>(kinetic_theory::UnequalTemperatureMixture{}.checked(cold));
  } catch (const std::domain_error& e) {
    expected = e.what();
  }
  CHECK(expected.find("state.temperatures[1]") != std::string::npos);
  CHECK(std::string(error.message) == expected);
  // The radial distribution's own domain: Σ α < 1.
  const double dense[] = {0.6, 0.5};
  CHECK(fluidbed_unequal_temperature_mixture(radial.get(), 1, 2, dense, temperatures, diameters, densities, restitution,
                                             pressure.data(), nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                                             nullptr, &error) == FLUIDBED_DOMAIN_ERROR);
  CHECK(std::string(error.message).find("sum of fractions") != std::string::npos);
  // Class counts, NULL inputs and closures of another family are invalid arguments.
  for (const std::size_t classes : {std::size_t(0), std::size_t(FLUIDBED_MAX_CLASSES + 1)}) {
    CHECK(fluidbed_unequal_temperature_mixture(radial.get(), 1, classes, fractions, temperatures, diameters, densities,
                                               restitution, pressure.data(), nullptr, nullptr, nullptr, nullptr,
                                               nullptr, nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
    CHECK(std::string(error.message).ends_with("classes; 1 to 10 are offered"));
  }
  CHECK(fluidbed_unequal_temperature_mixture(radial.get(), 3, 2, fractions, nullptr, diameters, densities, restitution,
                                             pressure.data(), nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                                             nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  const Handle carnahan = create("CarnahanStarling");
  CHECK(fluidbed_unequal_temperature_mixture(carnahan.get(), 3, 2, fractions, temperatures, diameters, densities,
                                             restitution, pressure.data(), nullptr, nullptr, nullptr, nullptr, nullptr,
                                             nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(std::string(error.message) ==
        "fluidbed: unequal_temperature_mixture: CarnahanStarling is not a mixture radial distribution");
  CHECK(fluidbed_unequal_temperature_mixture(nullptr, 3, 2, fractions, temperatures, diameters, densities, restitution,
                                             pressure.data(), nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                                             nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
}

TEST_CASE("C interface: bad input gives the checked API's error, the failing cell and its message") {
  const Handle law = create("SyamlalOBrien");
  const double voidage[] = {0.5, std::numeric_limits<double>::quiet_NaN(), 0.5};
  const double slip[] = {0.1, 0.1, 0.1}, density[] = {1.2, 1.2, 1.2}, viscosity[] = {1.8e-5, 1.8e-5, 1.8e-5},
               diameter[] = {3e-4, 3e-4, 3e-4};
  double beta[] = {-1, -1, -1};
  fluidbed_error error{};
  CHECK(fluidbed_drag(law.get(), FLUIDBED_BUOYANCY_CLASSICAL, 3, voidage, slip, density, viscosity, diameter, beta,
                      nullptr, nullptr, nullptr, &error) == FLUIDBED_DOMAIN_ERROR);
  CHECK(error.status == FLUIDBED_DOMAIN_ERROR);
  CHECK(error.index == 1);
  CHECK(beta[0] > 0);     // written below the failing cell
  CHECK(beta[2] == -1);   // not beyond it
  // The message is the checked C++ call's.
  std::string expected;
  try {
    drag::SyamlalOBrien{}.checked(drag::DragState<double>{voidage[1], 0.1, {1.2, 1.8e-5}, 3e-4});
  } catch (const std::domain_error& e) {
    expected = e.what();
  }
  CHECK(std::string(error.message) == expected);
  CHECK(std::string(error.message).find("voidage") != std::string::npos);

  // A NULL array, an unknown convention, a closure of another family, NULL handle.
  CHECK(fluidbed_drag(law.get(), FLUIDBED_BUOYANCY_CLASSICAL, 3, voidage, nullptr, density, viscosity, diameter, beta,
                      nullptr, nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(fluidbed_drag(law.get(), static_cast<fluidbed_buoyancy>(7), 1, voidage, slip, density, viscosity, diameter,
                      beta, nullptr, nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  const Handle radial = create("CarnahanStarling");
  CHECK(fluidbed_drag(radial.get(), FLUIDBED_BUOYANCY_CLASSICAL, 1, voidage, slip, density, viscosity, diameter, beta,
                      nullptr, nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  CHECK(std::string(error.message) == "fluidbed: drag: CarnahanStarling is not a drag law");
  CHECK(fluidbed_drag(nullptr, FLUIDBED_BUOYANCY_CLASSICAL, 1, voidage, slip, density, viscosity, diameter, beta,
                      nullptr, nullptr, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);
  // No cells: nothing read, nothing written, success (NULL arrays allowed).
  CHECK(fluidbed_drag(law.get(), FLUIDBED_BUOYANCY_CLASSICAL, 0, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                      nullptr, nullptr, nullptr, &error) == FLUIDBED_OK);
  CHECK(std::string(error.message).empty());
  // A negative Reynolds number, a negative Archimedes number; the error argument may be NULL.
  const Handle cd = create("SchillerNaumannCoefficient");
  const double negative = -1;
  double out = 0;
  CHECK(fluidbed_sphere_drag_coefficient(cd.get(), 1, &negative, &out, nullptr, nullptr) == FLUIDBED_DOMAIN_ERROR);
  const Handle ut = create("SchillerNaumannTerminalVelocity");
  CHECK(fluidbed_reynolds_of_archimedes(ut.get(), 1, &negative, &out, nullptr, &error) == FLUIDBED_DOMAIN_ERROR);
  CHECK(fluidbed_reynolds_of_archimedes(cd.get(), 1, &negative, &out, nullptr, &error) == FLUIDBED_INVALID_ARGUMENT);

  // Unknown names.
  fluidbed_closure* none = reinterpret_cast<fluidbed_closure*>(&error);
  CHECK(fluidbed_closure_create("NoSuchLaw", &none, &error) == FLUIDBED_UNKNOWN_NAME);
  CHECK(none == nullptr);
  CHECK(std::string(error.message).starts_with("fluidbed: unknown closure 'NoSuchLaw'; known: StokesCoefficient, "));
  CHECK(fluidbed_closure_create(nullptr, &none, &error) == FLUIDBED_INVALID_ARGUMENT);
}

TEST_CASE("C interface: the catalogue, metadata and parameters are the registries'") {
  std::vector<std::string> names;
  Registries::for_each([&](auto registry) {
    for (const auto& law : decltype(registry)::type::all()) names.emplace_back(decltype(registry)::type::name_of(law));
  });
  REQUIRE(fluidbed_closure_count() == names.size());
  for (std::size_t i = 0; i < names.size(); ++i) CHECK(names[i] == fluidbed_closure_name_at(i));
  CHECK(fluidbed_closure_name_at(names.size()) == nullptr);
  CHECK(std::string(fluidbed_family_what(FLUIDBED_DRAG_LAW)) == "drag law");
  CHECK(std::string(fluidbed_family_convention(FLUIDBED_DRAG_LAW)) == drag::DragLaws::family::convention);
  CHECK(fluidbed_family_what(FLUIDBED_FAMILY_COUNT) == nullptr);

  const Handle wen_yu = create("WenYu1966");
  CHECK(fluidbed_closure_family(wen_yu.get()) == FLUIDBED_DRAG_LAW);
  // The wall laws: by name, family and parameters (no array evaluation through C yet).
  const Handle wall = create("JenkinsLougeWall");
  CHECK(fluidbed_closure_family(wall.get()) == FLUIDBED_WALL_BOUNDARY_CONDITION);
  CHECK(std::string(fluidbed_family_what(FLUIDBED_WALL_BOUNDARY_CONDITION)) == "wall boundary condition");
  CHECK(fluidbed_closure_parameter_count(wall.get()) == 3);
  double friction = 0;
  fluidbed_error wall_error{};
  CHECK(fluidbed_closure_get_parameter(wall.get(), "wall_friction", &friction, &wall_error) == FLUIDBED_OK);
  CHECK(friction == 0.1);
  CHECK(fluidbed_closure_set_parameter(wall.get(), "wall_restitution", 1.5, &wall_error) == FLUIDBED_DOMAIN_ERROR);
  CHECK(std::string(fluidbed_closure_reference(wen_yu.get())) ==
        std::visit([](const auto& l) { return std::string(l.reference()); }, drag::DragLaws::make("WenYu1966")));
  REQUIRE(fluidbed_closure_validity_count(wen_yu.get()) == 2);
  const char* quantity = nullptr;
  double low = 0, high = 0;
  REQUIRE(fluidbed_closure_validity(wen_yu.get(), 0, &quantity, &low, &high, nullptr) == FLUIDBED_OK);
  CHECK(std::string(quantity) == "voidage");
  CHECK(low == 0.8);
  CHECK(fluidbed_closure_validity(wen_yu.get(), 2, &quantity, &low, &high, nullptr) == FLUIDBED_INVALID_ARGUMENT);

  REQUIRE(fluidbed_closure_parameter_count(wen_yu.get()) == 1);
  CHECK(std::string(fluidbed_closure_parameter_name(wen_yu.get(), 0)) == "exponent");
  double exponent = 0;
  REQUIRE(fluidbed_closure_get_parameter(wen_yu.get(), "exponent", &exponent, nullptr) == FLUIDBED_OK);
  CHECK(exponent == 2.7);
  // A parameter set through the interface is the C++ law's: WenYu1966 at 2.65 is WenYuGidaspow.
  Handle copy(fluidbed_closure_copy(wen_yu.get()));
  REQUIRE(fluidbed_closure_set_parameter(copy.get(), "exponent", 2.65, nullptr) == FLUIDBED_OK);
  const Handle gidaspow = create("WenYuGidaspow");
  const double e = 0.7, w = 0.3, rho = 1.2, mu = 1.8e-5, d = 3e-4;
  double a = 0, b = 0, original = 0;
  fluidbed_drag(copy.get(), FLUIDBED_BUOYANCY_CLASSICAL, 1, &e, &w, &rho, &mu, &d, &a, nullptr, nullptr, nullptr, nullptr);
  fluidbed_drag(gidaspow.get(), FLUIDBED_BUOYANCY_CLASSICAL, 1, &e, &w, &rho, &mu, &d, &b, nullptr, nullptr, nullptr,
                nullptr);
  fluidbed_drag(wen_yu.get(), FLUIDBED_BUOYANCY_CLASSICAL, 1, &e, &w, &rho, &mu, &d, &original, nullptr, nullptr,
                nullptr, nullptr);
  CHECK(same_bits(a, b));
  CHECK(a != original);  // the copy is a copy

  fluidbed_error error{};
  CHECK(fluidbed_closure_set_parameter(copy.get(), "c1", 1.0, &error) == FLUIDBED_UNKNOWN_PARAMETER);
  CHECK(std::string(error.message) == "fluidbed: WenYu1966 has no parameter 'c1'; its parameters: exponent");
  const Handle syamlal = create("SyamlalOBrien");
  CHECK(fluidbed_closure_set_parameter(syamlal.get(), "c1", -1.0, &error) == FLUIDBED_DOMAIN_ERROR);
  CHECK(std::string(error.message) ==
        "fluidbed::SyamlalOBrien: argument 'c1' = -1 is out of domain (must be finite and > 0)");
  double c1 = 0;
  CHECK(fluidbed_closure_get_parameter(syamlal.get(), "c1", &c1, nullptr) == FLUIDBED_OK);
  CHECK(c1 == 0.8);  // unchanged
  CHECK(std::string(fluidbed_status_name(FLUIDBED_DOMAIN_ERROR)) == "FLUIDBED_DOMAIN_ERROR");
}

TEST_CASE("C interface: one handle evaluated from 8 threads at once gives the serial results") {
  const Handle law = create("MazzeiLettieri");
  constexpr std::size_t n = 4096;
  std::vector<double> voidage(n), slip(n), density(n, 1.2), viscosity(n, 1.8e-5), diameter(n, 3e-4), serial(n);
  for (std::size_t i = 0; i < n; ++i) {
    voidage[i] = 0.4 + 0.59 * static_cast<double>(i) / n;
    slip[i] = 1e-3 * static_cast<double>(i % 97);
  }
  const auto evaluate = [&](double* beta) {
    return fluidbed_drag(law.get(), FLUIDBED_BUOYANCY_PRESSURE_GRADIENT, n, voidage.data(), slip.data(),
                         density.data(), viscosity.data(), diameter.data(), beta, nullptr, nullptr, nullptr, nullptr);
  };
  REQUIRE(evaluate(serial.data()) == FLUIDBED_OK);
  std::vector<std::vector<double>> results(8, std::vector<double>(n));
  std::vector<fluidbed_status> statuses(8);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < 8; ++t) threads.emplace_back([&, t] { statuses[t] = evaluate(results[t].data()); });
  for (std::thread& thread : threads) thread.join();
  for (std::size_t t = 0; t < 8; ++t) {
    CHECK(statuses[t] == FLUIDBED_OK);
    CHECK(std::memcmp(results[t].data(), serial.data(), n * sizeof(double)) == 0);
  }
}
