// Every monodisperse drag law of the library side by side against the voidage, for two
// particle/fluid systems at a fixed superficial velocity u_s (interstitial slip w = u_s/ε, so
// Re = ρ_f u_s d/μ_f is the same all along each curve):
//
//   Geldart A powder in air    FCC powder 1 of seed 000 Table 4.5 (d 137 µm, ρ_p 1210 kg/m³),
//                              air ρ_f 1.205 kg/m³, μ_f 1.81e-5 Pa s, u_s = 2.0 cm/s (Re ≈ 0.18)
//   glass beads in water       seed 000 Table 4.3 system 3 (Wilhelm & Kwauk 1948; d 5.21 mm,
//                              ρ_p 2351 kg/m³), water ρ_f 1005 kg/m³, μ_f 1.00e-3 Pa s,
//                              u_s = 0.111 m/s (a Table 4.4 row; Re ≈ 581)
//
// plotted as the dimensionless drag force (drag-only normalisation, dimensionless_force.hpp)
//
//   F = β_classical d²/(18 μ_f (1 − ε)) = β_pressure_gradient d²/(18 μ_f ε (1 − ε)),
//
// the drag on a particle over the Stokes drag 3π μ_f d ε w at the superficial slip. The buoyant
// weight is the straight line F_w = (ρ_p − ρ_f) g d² ε/(18 μ_f u_s) (eq. 3.28 in these units), so
// each law's homogeneous-bed voidage at this u_s is where its curve crosses the line; the table
// lists them beside Richardson–Zaki's (eqs. 3.22, 3.24).
//
// Checks (the program fails if one does not hold):
//   - Stokes limit: as ε → 1 and Re → 0 (φ = 1e-10, Re = 1e-12) F tends to 1 for every law whose
//     single-sphere drag is Stokes's (Schiller–Naumann C_D Re → 24, and the lattice-Boltzmann
//     fits, F0(0) = 1), to 23.04/24 = 0.96 for those built on Dallavalle's C_D, to the blend weight
//     ψ(1) = 0.99394 for Gidaspow's arctan blend (Ergun keeps 0.6 % weight at ε = 1) and to 0 for
//     Ergun (a packed-bed law); within 1e-3 (Tenneti's φ^⅓ term is 2e-4 at φ = 1e-10).
//   - Gidaspow's switch at ε = 0.8: Ergun just below, Wen–Yu (α = 2.65) at 0.8, the blend exactly
//     their mean there (relative 1e-12); the jump Wen–Yu/Ergun at 0.8 against the values of the
//     seed 002 note §2.4 (0.8886, 0.9422, 0.9472, 0.5772, 0.2679 at Re = 0.1 … 1000; ± 6e-5,
//     half a unit of their last digit).
//   - Mazzei–Lettieri's equilibrium voidage equals Richardson–Zaki's (relative 1e-9), and Ergun's
//     minimum fluidization velocity at ε = 0.4 for the 137 µm FCC in air of seed 000 eq. 4.5
//     (ρ_f 1.18, μ_f 1.81e-5) is the printed 8.73e-3 m/s (± 0.005e-3, its last digit).
//
//   drag_laws_vs_voidage [output directory for the plots; none: no plots]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fluidbed/drag/any_drag_law.hpp"
#include "fluidbed/settling.hpp"
#include "plot.hpp"

namespace {

using namespace fluidbed;
using drag::AnyDragLaw;
using drag::DragState;

struct System {
  const char* name;
  const char* short_name;
  const char* file;
  const char* yrange;
  Fluid<double> fluid;
  Particles<double> particles;
  double superficial_velocity;
};

const System systems[] = {
    {"FCC powder 1 (137 µm, 1210 kg/m³) in air, u_s = 2.0 cm/s",
     "FCC in air",
     "drag_laws_fcc_in_air",
     "[0.5:100]",
     {1.205, 1.81e-5},
     {1210.0, 137e-6},
     0.020},
    {"glass beads (5.21 mm, 2351 kg/m³) in water, u_s = 0.111 m/s",
     "glass in water",
     "drag_laws_glass_in_water",
     "[5:1000]",
     {1005.0, 1.00e-3},
     {2351.0, 5.21e-3},
     0.111},
};

// F = β_classical d²/(18 μ_f φ) at voidage ε and superficial velocity u_s.
double dimensionless_force(const AnyDragLaw& law, const System& s, double voidage) {
  const double slip = s.superficial_velocity / voidage;
  const double beta = drag::evaluate(law, DragState<double>{voidage, slip, s.fluid, s.particles.diameter}).classical();
  const double d = s.particles.diameter;
  return beta * d * d / (18 * s.fluid.viscosity * (1 - voidage));
}

// The buoyant weight in the same units: (ρ_p − ρ_f) g d² ε/(18 μ_f u_s).
double weight_line(const System& s, double voidage) {
  const double d = s.particles.diameter;
  return (s.particles.density - s.fluid.density) * standard_gravity * d * d * voidage /
         (18 * s.fluid.viscosity * s.superficial_velocity);
}

// The limit of F as ε → 1 and Re → 0 each law should reach, and why.
struct StokesLimit {
  double value;
  const char* reason;
};

StokesLimit stokes_limit(std::string_view name) {
  if (name == "Ergun") return {0.0, "packed-bed law: no single-particle limit"};
  if (name == "GidaspowBlended")
    return {drag::GidaspowBlended::blending_weight(1.0), "blend weight psi(1): Ergun keeps weight 1 - psi"};
  if (name == "DiFeliceDallavalle" || name == "MazzeiLettieri" || name == "SyamlalOBrien")
    return {23.04 / 24, "Dallavalle C_D Re -> 4.8^2 = 23.04"};
  if (name == "VanDerHoef2005" || name == "Beetstra2007" || name == "Tang2015" || name == "Tenneti2011" ||
      name == "KochHill")
    return {1.0, "lattice-Boltzmann fit, isolated-sphere limit F0 = 1"};
  return {1.0, "Schiller-Naumann C_D Re -> 24"};
}

// Line styles for the plot: colour and dash type per law.
const char* const colours[] = {"#000000", "#e69f00", "#56b4e9", "#009e73", "#0072b2", "#d55e00", "#cc79a7", "#999999"};

plot::Panel panel_of(const System& s) {
  const double re = s.fluid.density * s.superficial_velocity * s.particles.diameter / s.fluid.viscosity;
  char title[160];
  std::snprintf(title, sizeof title, "%s (Re = %.3g)", s.name, re);
  plot::Panel panel(title, "voidage ε",
                    "F = β d_p^2 / (18 μ_f (1 − ε))   (drag / Stokes drag at the superficial slip)");
  panel.log_y = true;
  panel.xrange = "[0.35:1]";
  panel.yrange = s.yrange;
  panel.key = "outside right";
  panel.commands = {"set format y '%g'"};
  const int n = 131;
  auto grid = [&](int i) { return 0.35 + 0.005 * i; };
  // Gidaspow's switched law underneath, thick and light, so that its jump stands out.
  int style = 0;
  for (const AnyDragLaw& law : drag::all_drag_laws) {
    const std::string name(drag::name_of(law));
    if (name == "Lewis1949") continue;  // the same numbers as WenYuGidaspow (constant_exponent.hpp)
    std::string how;
    if (name == "GidaspowSwitched") {
      how = "lines lw 7 lc rgb '#c8c8c8'";
    } else {
      how =
          std::string("lines lw 2 lc rgb '") + colours[(style + style / 8) % 8] + "' dt " + (style < 8 ? "1" : "(6,4)");
      ++style;
    }
    plot::Series& curve = panel.add(name == "WenYuGidaspow" ? "WenYuGidaspow (= Lewis1949)" : name, how);
    for (int i = 0; i < n; ++i) {
      const double e = std::min(grid(i), 0.999);
      if (name == "GidaspowSwitched" && e >= 0.8 && grid(i - 1) < 0.8) {  // the jump, as a gap
        curve.point(0.8 - 1e-9, dimensionless_force(law, s, 0.8 - 1e-9)).gap();
        curve.point(0.8, dimensionless_force(law, s, 0.8));
      }
      curve.point(e, dimensionless_force(law, s, e));
    }
  }
  panel.add("buoyant weight (eq. 3.28)", "lines lw 4 lc 'black' dt (2,3)")
      .point(0.35, weight_line(s, 0.35))
      .point(1, weight_line(s, 1));
  return panel;
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<std::string> directory = plot::output_directory(argc, argv);
  std::printf(
      "Every monodisperse drag law against the voidage, at a fixed superficial velocity, as the dimensionless\n"
      "force F = beta_classical d^2/(18 mu_f (1 - eps)); eps_eq is the law's homogeneous-bed voidage (eq. 3.28).\n\n");
  int failures = 0;
  const double table_voidages[] = {0.40, 0.50, 0.60, 0.79, 0.80, 0.95};
  for (const System& s : systems) {
    const double re = s.fluid.density * s.superficial_velocity * s.particles.diameter / s.fluid.viscosity;
    const std::optional<double> rz =
        settling::richardson_zaki_equilibrium_voidage(s.superficial_velocity, s.fluid, s.particles);
    std::printf("%s (Re = %.4g); Richardson-Zaki eps = %.4f\n", s.short_name, re, rz ? *rz : -1.0);
    std::printf("  %-26s %-9s", "law", "native");
    for (double e : table_voidages) std::printf("  F(%.2f) ", e);
    std::printf("  eps_eq\n");
    for (const AnyDragLaw& law : drag::all_drag_laws) {
      const std::string name(drag::name_of(law));
      const bool classical =
          std::visit([](const auto& l) { return l.native_buoyancy == drag::Buoyancy::classical; }, law);
      std::printf("  %-26s %-9s", name.c_str(), classical ? "classical" : "press.gr.");
      for (double e : table_voidages) std::printf(" %9.4g", dimensionless_force(law, s, e));
      const std::optional<double> eq = settling::equilibrium_voidage(law, s.superficial_velocity, s.fluid, s.particles);
      if (eq)
        std::printf("   %.4f\n", *eq);
      else
        std::printf("   no bed\n");
      if (name == "MazzeiLettieri") {
        const bool ok = eq && rz && std::abs(*eq / *rz - 1) <= 1e-9;
        failures += !ok;
        if (!ok) std::printf("  FAIL: Mazzei-Lettieri's equilibrium voidage differs from Richardson-Zaki's\n");
      }
    }
    std::printf("\n");
  }

  std::printf("Stokes limit: F at eps = 1 - 1e-10, Re = 1e-12 (tolerance 1e-3)\n");
  {
    const Fluid<double> unit{1.0, 1.0};
    const double phi = 1e-10, voidage = 1 - phi, re = 1e-12;
    for (const AnyDragLaw& law : drag::all_drag_laws) {
      const std::string name(drag::name_of(law));
      const double beta = drag::evaluate(law, DragState<double>{voidage, re / voidage, unit, 1.0}).classical();
      const double f = beta / (18 * phi);
      const StokesLimit expected = stokes_limit(name);
      const bool ok = std::abs(f - expected.value) <= 1e-3;
      failures += !ok;
      std::printf("  %-24s F = %.6f  expected %.6f  (%s)%s\n", name.c_str(), f, expected.value, expected.reason,
                  ok ? "" : "   FAIL");
    }
  }

  std::printf("\nGidaspow's switch at eps = 0.8 (pressure-gradient beta; Re = rho_f eps w d/mu_f)\n");
  {
    const Fluid<double> unit{1.0, 1.0};
    const double note_ratio[] = {0.8886, 0.9422, 0.9472, 0.5772, 0.2679};
    const double reynolds[] = {0.1, 1, 10, 100, 1000};
    for (int i = 0; i < 5; ++i) {
      const double e = 0.8, slip = reynolds[i] / e;
      const DragState<double> at{e, slip, unit, 1.0}, below{std::nextafter(e, 0.0), slip, unit, 1.0};
      const double ergun = drag::Ergun{}(at).pressure_gradient();
      const double wen_yu = drag::GidaspowSwitched::pressure_gradient_wen_yu(e, slip, unit, 1.0);
      const double switched_at = drag::GidaspowSwitched{}(at).pressure_gradient();
      const double switched_below = drag::GidaspowSwitched{}(below).pressure_gradient();
      const double ergun_below = drag::Ergun{}(below).pressure_gradient();
      const double blended = drag::GidaspowBlended{}(at).pressure_gradient();
      const bool identities = std::abs(switched_at / wen_yu - 1) <= 1e-12 &&
                              std::abs(switched_below / ergun_below - 1) <= 1e-12 &&
                              std::abs(blended / (0.5 * (ergun + wen_yu)) - 1) <= 1e-12;
      const double ratio = wen_yu / ergun;
      const bool ok = identities && std::abs(ratio - note_ratio[i]) <= 6e-5;
      failures += !ok;
      std::printf(
          "  Re %-6g WenYu/Ergun = %.5f (note %.4f); switched = Ergun below, WenYu at 0.8; blend = mean: %s%s\n",
          reynolds[i], ratio, note_ratio[i], identities ? "yes" : "NO", ok ? "" : "   FAIL");
    }
  }

  std::printf(
      "\nSeed 000 eq. 4.5: Ergun u_mf at eps = 0.4, FCC 137 um / 1210 kg/m3 in air (rho_f 1.18, mu_f 1.81e-5)\n");
  {
    const Fluid<double> air{1.18, 1.81e-5};
    const Particles<double> fcc{1210.0, 137e-6};
    const double u_mf = settling::minimum_fluidization_velocity_ergun(air, fcc, 0.4);
    const std::optional<double> eq = settling::equilibrium_voidage(drag::Ergun{}, 8.73e-3, air, fcc);
    const bool ok = std::abs(u_mf - 8.73e-3) <= 0.005e-3 && eq && std::abs(*eq - 0.4) <= 5e-4;
    failures += !ok;
    std::printf(
        "  u_mf = %.5e m/s (thesis 8.73e-3); Ergun drag at u_s = 8.73e-3 m/s balances the weight at eps = %.5f%s\n",
        u_mf, eq ? *eq : -1.0, ok ? "" : "   FAIL");
  }

  if (directory) {
    for (const System& s : systems) {
      const std::string png = plot::render(*directory, s.file, {panel_of(s)}, 1150, 650);
      if (!png.empty()) std::printf("plotted %s\n", png.c_str());
    }
  } else {
    std::printf("\n(no output directory given: no plot)\n");
  }
  if (failures) std::printf("%d checks FAILED\n", failures);
  return failures == 0 ? 0 : 1;
}
