// The drag family in float, double and long double: the row tests of test_scalar_types_drag.hpp
// (every law, the polydisperse Beetstra law and C_D·Re against the mpmath table), and the switch
// points in the argument's type.
#include "test_scalar_types_drag.hpp"

#include <doctest/doctest.h>

#include <cmath>

#include "fluidbed/drag.hpp"

using namespace fluidbed;
using namespace fluidbed::drag;

TEST_CASE_TEMPLATE_INVOKE(scalar_types_drag_laws, FLUIDBED_SCALAR_TYPES);
TEST_CASE_TEMPLATE_INVOKE(scalar_types_single_sphere, FLUIDBED_SCALAR_TYPES);
TEST_CASE_TEMPLATE_INVOKE(scalar_types_beetstra, FLUIDBED_SCALAR_TYPES);

// A switch point is compared with the argument in the argument's type: the decimal rounded
// once to T, so that the documented side of a switch holds at the switch itself in every type
// (0.8L lies below the double 0.8 and 0.85L above the double 0.85: compared with double switch
// points, long double arguments equal to the switch took the other branch). At the switch the
// law equals its value one ulp on the documented side and jumps one ulp on the other.
TEST_CASE_TEMPLATE("switch points of the drag laws lie at the decimal in the argument's type", T,
                   FLUIDBED_SCALAR_TYPES) {
  const Fluid<T> air{T(1.25L), T(1.8e-5L)};
  const T d = T(5e-4L);
  const auto jump = [](const T& at_switch, const T& neighbour) { return std::abs(neighbour - at_switch) / at_switch; };
  // Gidaspow: Ergun below ε = 0.8, Wen–Yu from 0.8 on (Wen–Yu/Ergun = 0.89 at Re = 0.1)
  const auto gidaspow = [&](const T& voidage) {
    return GidaspowSwitched{}(DragState<T>{voidage, T(0.005L), air, d}).pressure_gradient();
  };
  const T gidaspow_switch = T(0.8L);
  CHECK(jump(gidaspow(gidaspow_switch), gidaspow(std::nextafter(gidaspow_switch, T(1)))) < 1e-5);
  CHECK(jump(gidaspow(gidaspow_switch), gidaspow(std::nextafter(gidaspow_switch, T(0)))) > 0.05);
  // Syamlal–O'Brien: B = c1 ε^1.28 up to ε = 0.85 inclusive (MFiX's rule), ε^d1 above; at
  // Re_s = 1000, V_r ≈ B and the branches differ by 0.05 % (c1 = 0.8, d1 = 2.65)
  const SyamlalOBrien syamlal;
  const auto ratio = [&](const T& voidage) { return syamlal.velocity_ratio(voidage, T(1000)); };
  const T syamlal_switch = T(0.85L);
  CHECK(jump(ratio(syamlal_switch), ratio(std::nextafter(syamlal_switch, T(0)))) < 1e-5);
  CHECK(jump(ratio(syamlal_switch), ratio(std::nextafter(syamlal_switch, T(1)))) > 2e-4);
  // Schiller–Naumann: the 0.44 branch from Re = 1000 on
  CHECK(single_particle::SchillerNaumannCoefficient::cd_times_re(T(1000)) == T(0.44L) * T(1000));
}
