// The unequal-temperature mixture (kinetic_theory/unequal_temperature_mixture.hpp) against the
// independent mpmath generator tests/reference/ktgf_classes_reference.py: every pair term, class
// quantity and matrix entry of 21 cells of 1 to 4 classes, with its partial derivatives in every
// class's volume fraction and granular temperature. The generator checks its own formulas
// against seed 004's numbers, the one-class theory, the Garzó–Dufty Maxwellian energy
// production rates and a quadrature of the Enskog collision integral.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

#include "fluidbed/kinetic_theory.hpp"
#include "kinetic_theory_table_names.hpp"
#include "reference_table.hpp"

using namespace fluidbed;
using namespace fluidbed::kinetic_theory;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

struct Worst {
  double value = 0, derivative = 0;
  int rows = 0;
};

template <std::size_t N>
GranularClassesState<double, N> state_of(const test::ReferenceTable& table, std::size_t row) {
  GranularClassesState<double, N> s{};
  for (std::size_t m = 0; m < N; ++m) {
    const std::string index = std::to_string(m);
    s.fractions[m] = table.number(row, "a" + index);
    s.temperatures[m] = table.number(row, "theta" + index);
    s.diameters[m] = table.number(row, "d" + index);
    s.densities[m] = table.number(row, "rho" + index);
  }
  s.restitution = table.number(row, "restitution");
  return s;
}

// The entry `quantity` (i, k) of the evaluation: a pair term, a class quantity or a matrix entry.
template <class Mixture, std::size_t N>
ClassSensitivity<double, N> entry(const Mixture& mixture, const GranularClassesState<double, N>& s,
                                  const std::string& quantity, std::size_t i, std::size_t k) {
  const auto v = mixture.with_derivatives(s);
  if (quantity == "radial_distribution") return v.radial_distribution[i][k];
  if (quantity == "pressure") return v.pressure[i];
  if (quantity == "energy_sink") return v.dissipation[i];
  if (quantity == "viscosity") return v.shear_viscosity[i][k];
  if (quantity == "conductivity") return v.conductivity[i][k];
  if (quantity == "drag_coefficient" && i != k) return v.drag[i][k];
  if (quantity == "segregation_coefficient" && i != k) return v.segregation[i][k];
  const auto t = mixture.pair_terms_with_derivatives(s, i, k);
  const ClassSensitivity<double, N>* x = nullptr;
  if (quantity == "contact_factor") x = &t.contact_factor;
  if (quantity == "pair_pressure") x = &t.pressure;
  if (quantity == "pair_viscosity_own") x = &t.viscosity_own;
  if (quantity == "pair_viscosity_partner") x = &t.viscosity_partner;
  if (quantity == "pair_conductivity_own") x = &t.conductivity_own;
  if (quantity == "pair_conductivity_partner") x = &t.conductivity_partner;
  if (quantity == "pair_energy_sink") x = &t.energy_sink;
  if (quantity == "drag_coefficient") x = &t.drag;
  if (quantity == "segregation_coefficient") x = &t.segregation;
  if (x == nullptr) throw std::invalid_argument("no quantity " + quantity);
  return *x;
}

template <std::size_t N>
void check_row(const test::ReferenceTable& table, std::size_t row, Worst& worst) {
  const auto s = state_of<N>(table, row);
  const std::string rdf = table.text(row, "rdf"), quantity = table.text(row, "quantity");
  const auto i = static_cast<std::size_t>(table.number(row, "i"));
  const int k_column = static_cast<int>(table.number(row, "k"));
  const std::size_t k = k_column < 0 ? i : static_cast<std::size_t>(k_column);
  ClassSensitivity<double, N> r{};
  if (rdf == "ModifiedMansoori")
    r = entry(UnequalTemperatureMixture{ModifiedMansoori{table.number(row, "max_packing")}}, s, quantity, i, k);
  else if (rdf == "Mansoori")
    r = entry(UnequalTemperatureMixture{Mansoori{}}, s, quantity, i, k);
  else
    throw std::invalid_argument("no mixture radial distribution " + rdf);
  CAPTURE(table.text(row, "case"));
  CAPTURE(quantity);
  CAPTURE(i);
  CAPTURE(k);
  const double reference = table.number(row, "value");
  const double value_error = test::relative_difference(r.value, reference);
  // The energy exchange is a difference, 2(M_i Θ_i − M_k Θ_k) + M_k (1 − e)(Θ_i + Θ_k), that
  // cancels where the classes are near their elastic balance: it is held to 1024 ε.
  const bool difference = quantity == "pair_energy_sink" || quantity == "energy_sink";
  CHECK(value_error < (difference ? 1024 : 64) * eps);
  worst.value = std::max(worst.value, value_error);
  // A derivative is compared on the scale of value/x, the size a derivative of a smooth
  // function of x has: an entry that cancels to near zero is not held to relative accuracy.
  for (std::size_t m = 0; m < N; ++m) {
    const std::string index = std::to_string(m);
    const double slopes[2] = {r.d_fractions[m], r.d_temperatures[m]};
    const double references[2] = {table.number(row, "d_a" + index), table.number(row, "d_theta" + index)};
    const double variables[2] = {s.fractions[m], s.temperatures[m]};
    for (int j = 0; j < 2; ++j) {
      const double scale = std::abs(references[j]) + (variables[j] > 0 ? std::abs(reference) / variables[j] : 0.0);
      const double error = scale > 0 ? std::abs(slopes[j] - references[j]) / scale : std::abs(slopes[j]);
      CHECK(error < 256 * eps);
      worst.derivative = std::max(worst.derivative, error);
    }
  }
  ++worst.rows;
}

}  // namespace

TEST_CASE("unequal-temperature mixture agrees with the mpmath reference, derivatives included") {
  const test::ReferenceTable table("ktgf_classes_reference.csv");
  Worst worst;
  for (std::size_t row = 0; row < table.size(); ++row) {
    switch (static_cast<int>(table.number(row, "n_classes"))) {
      case 1: check_row<1>(table, row, worst); break;
      case 2: check_row<2>(table, row, worst); break;
      case 3: check_row<3>(table, row, worst); break;
      case 4: check_row<4>(table, row, worst); break;
      default: FAIL("unexpected class count");
    }
  }
  CHECK(worst.rows == static_cast<int>(table.size()));
  CHECK(worst.rows >= 1800);
  MESSAGE("worst relative error: value " << worst.value << ", derivative " << worst.derivative << " over "
                                         << worst.rows << " rows");
}
