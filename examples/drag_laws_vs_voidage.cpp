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
// The plots (drag_laws_fcc_in_air.png, drag_laws_glass_in_water.png): per system, three panels
// (packed-bed and constant-exponent laws; voidage functions on a single-sphere C_D; fits to
// simulations of fixed arrays), each law in its own colour, marker and dash, thick where the
// state lies inside the validity range the law declares (ValidityRange: ε and Re), thin dotted
// outside it; the legend gives that range and the law's homogeneous-bed voidage ε_eq, marked
// where the curve meets the weight line; Richardson–Zaki's ε is the vertical line. β is in the
// classical-buoyancy convention, as the y axis says (codes with −φ∇p buoyancy use ε β).
//
// Checks (the program fails if one does not hold):
//   - Stokes limit: as ε → 1 and Re → 0 (φ = 1e-10, Re = 1e-12) F tends to 1 for every law whose
//     single-sphere drag is Stokes's (Schiller–Naumann C_D Re → 24, and the lattice-Boltzmann
//     fits, F0(0) = 1), to 23.04/24 = 0.96 for those built on Dallavalle's C_D, to the blend weight
//     ψ(1) = 0.99394 for Gidaspow's arctan blend (Ergun keeps 0.6 % weight at ε = 1) and to 0 for
//     Ergun (a packed-bed law); within 1e-3 (Tenneti's φ^⅓ term is 2e-4 at φ = 1e-10).
//   - Gidaspow's switch at ε = 0.8: Ergun just below, Wen–Yu (α = 2.65) at 0.8, the blend exactly
//     their mean there (relative 1e-12); the jump Wen–Yu/Ergun at 0.8, i.e.
//     ¾ C_D Re ε^−1.65/(150 φ + 1.75 Re) of van der Hoef et al. (2006) eqs. (45)–(46) (seed 002)
//     with the Schiller–Naumann C_D, evaluated independently in Python: 0.8886, 0.9422, 0.9472,
//     0.5772, 0.2679 at Re = 0.1 … 1000 (± 6e-5, half a unit of their last digit).
//   - What the plot draws: every law's equilibrium voidage ε_eq (the large marker) is where its F
//     meets the weight line (relative 1e-8; at Gidaspow's jump the line passes between the two
//     sides), and Lewis, left out of the plot, gives WenYuGidaspow's F at every plotted ε
//     (relative 1e-15), as the legend says.
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
#include <variant>
#include <vector>

#include "fluidbed/drag/any_drag_law.hpp"
#include "fluidbed/fluidization.hpp"
#include "fluidbed/settling.hpp"
#include "fluidbed/single_particle.hpp"
#include "plot.hpp"

namespace {

using namespace fluidbed;
using drag::AnyDragLaw;
using drag::DragState;
using drag::ValidityRange;

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
     "[1:1000]",
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

constexpr double plotted_voidage_min = 0.35, plotted_voidage_max = 0.999;

// The plot's grid: 0.35, 0.355, …, 0.995, 0.999.
std::vector<double> plotted_voidages() {
  std::vector<double> voidages;
  for (int i = 0; i <= 130; ++i) voidages.push_back(std::min(plotted_voidage_min + 0.005 * i, plotted_voidage_max));
  return voidages;
}

// True if the law's F meets the weight line at ε_eq: equal there, or, at the jump of Gidaspow's
// switched law (where equilibrium_voidage returns the jump), between the two sides.
bool meets_weight_line(const AnyDragLaw& law, const System& s, double equilibrium) {
  const double weight = weight_line(s, equilibrium), at = dimensionless_force(law, s, equilibrium);
  if (std::abs(at / weight - 1) <= 1e-8) return true;
  const double below = dimensionless_force(law, s, std::nextafter(equilibrium, 0.0));
  return std::holds_alternative<drag::GidaspowSwitched>(law) &&
         equilibrium == drag::GidaspowSwitched::switch_voidage<double>() && std::min(at, below) <= weight &&
         weight <= std::max(at, below);
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
  if (name == "VanDerHoef" || name == "Beetstra" || name == "Tang" || name == "Tenneti" ||
      name == "KochHill")
    return {1.0, "lattice-Boltzmann fit, isolated-sphere limit F0 = 1"};
  return {1.0, "Schiller-Naumann C_D Re -> 24"};
}

double reynolds_of(const System& s) {
  return s.fluid.density * s.superficial_velocity * s.particles.diameter / s.fluid.viscosity;
}

ValidityRange validity_of(const AnyDragLaw& law) {
  return std::visit([](const auto& l) { return l.validity(); }, law);
}

// A Reynolds number bound for a legend: 300, 1000, 10^{4}.
std::string bound_text(double re) {
  char text[32];
  const double decade = std::round(std::log10(re));
  if (re >= 1e4 && re == std::pow(10.0, decade))
    std::snprintf(text, sizeof text, "10^{%.0f}", decade);
  else
    std::snprintf(text, sizeof text, "%g", re);
  return text;
}

// "ε 0.4–0.9, Re ≤ 1000": the range a law declares it was fitted or derived for.
std::string validity_text(const ValidityRange& v) {
  char text[32];
  std::snprintf(text, sizeof text, "ε %.2g–%.2g", v.voidage_min, v.voidage_max);
  const std::string voidage = v.voidage_min <= 0 && v.voidage_max >= 1 ? "all ε" : text;
  if (v.reynolds_min <= 0 && std::isinf(v.reynolds_max)) return voidage + ", all Re";
  if (v.reynolds_min <= 0) return voidage + ", Re ≤ " + bound_text(v.reynolds_max);
  return voidage + ", " + bound_text(v.reynolds_min) + " ≤ Re ≤ " + bound_text(v.reynolds_max);
}

bool within(const ValidityRange& v, double voidage, double re) {
  return voidage >= v.voidage_min && voidage <= v.voidage_max && re >= v.reynolds_min && re <= v.reynolds_max;
}

// The plot's panels: the laws grouped by kind, at most six curves each. A law of the family
// that no group names (a later addition) gets a panel of its own kind, "other laws".
struct Group {
  const char* title;
  std::vector<std::string_view> laws;
};

const Group law_groups[] = {
    {"Packed-bed and constant-exponent laws",
     {"GidaspowSwitched", "Ergun", "WenYu1966", "Kmiec", "WenYuGidaspow", "GidaspowBlended"}},
    {"Voidage functions on a single-sphere C_D",
     {"DiFeliceDallavalle", "DiFeliceSchillerNaumann", "MazzeiLettieri", "SyamlalOBrien"}},
    {"Fits to simulations of fixed random arrays", {"VanDerHoef", "Beetstra", "Tang", "Tenneti", "KochHill"}},
};

// One law's curve: a thick line where the state lies inside the law's declared validity, a thin
// dotted one outside it (in ε, or all along when the Re of the system is outside), the same
// colour and markers on both; and its homogeneous equilibrium, a large marker on the weight line.
void add_law(plot::Panel& panel, const AnyDragLaw& law, int index, const System& s) {
  const std::string name(drag::name_of(law));
  const ValidityRange v = validity_of(law);
  const double re = reynolds_of(s);
  const bool switched = std::holds_alternative<drag::GidaspowSwitched>(law);
  const double jump = drag::GidaspowSwitched::switch_voidage<double>();

  std::vector<double> voidages = plotted_voidages();
  for (double bound : {v.voidage_min, v.voidage_max})
    if (bound > plotted_voidage_min && bound < plotted_voidage_max) voidages.push_back(bound);
  if (switched) voidages.push_back(std::nextafter(jump, 0.0));
  std::sort(voidages.begin(), voidages.end());
  voidages.erase(std::unique(voidages.begin(), voidages.end()), voidages.end());

  // Gidaspow's switched law is Ergun below 0.8 and WenYuGidaspow from 0.8: drawn wide and grey
  // underneath those two, so that its jump stands out.
  const plot::Look look = plot::look(index);
  const std::string inside_style = switched ? "lines lw 7 lc rgb '#d0d0d0'" : look.line(2.5);
  const std::string outside_style = switched ? "lines lw 3 dt (2,3) lc rgb '#d0d0d0'" : look.line(1.2, "(2,3)");
  std::optional<double> equilibrium =
      fluidization::equilibrium_voidage(law, s.superficial_velocity, s.fluid, s.particles);
  std::string title = (name == "WenYuGidaspow" ? "WenYuGidaspow (= Lewis)" : name) + "   [" + validity_text(v) + "]";
  char text[64];
  if (!equilibrium)
    std::snprintf(text, sizeof text, ": no bed");
  else if (*equilibrium < plotted_voidage_min)
    std::snprintf(text, sizeof text, ": ε_{eq} %.3f, off scale", *equilibrium);
  else
    std::snprintf(text, sizeof text, ": ε_{eq} %.3f", *equilibrium);
  title += text;

  bool any_inside = false;
  for (double e : voidages) any_inside = any_inside || within(v, e, re);
  plot::Series& inside = panel.add(any_inside ? title : "", inside_style);
  plot::Series& outside = panel.add(any_inside ? "" : title, outside_style);
  if (!switched) {
    inside.with_markers(look.marker(), 14, 3 * index);
    outside.with_markers(look.marker(1.0), 14, 3 * index);
  }
  for (std::size_t i = 0; i < voidages.size(); ++i) {
    const double e = voidages[i];
    if (switched && e == jump) inside.gap(), outside.gap();
    const double f = dimensionless_force(law, s, e);
    const bool in = within(v, e, re);
    // A boundary sample belongs to both parts, so that the thick and the thin line meet.
    const bool next_to_outside = (i > 0 && !within(v, voidages[i - 1], re)) ||
                                 (i + 1 < voidages.size() && !within(v, voidages[i + 1], re));
    if (in)
      inside.point(e, f);
    else
      inside.gap();
    if (!in || next_to_outside)
      outside.point(e, f);
    else
      outside.gap();
  }
  if (equilibrium && *equilibrium >= plotted_voidage_min)
    panel.add("", switched ? "points pt 7 ps 2.6 lc rgb '#a0a0a0'" : "points " + look.marker(2.2))
        .point(*equilibrium, weight_line(s, *equilibrium));
}

std::vector<plot::Panel> panels_of(const System& s, std::optional<double> richardson_zaki) {
  std::vector<plot::Panel> panels;
  std::vector<int> drawn(std::size(law_groups) + 1, 0);
  const auto panel_for = [&](std::size_t group) -> plot::Panel& {
    while (panels.size() <= group) {
      const std::size_t g = panels.size();
      // The y axis, the same for all panels, is labelled once.
      plot::Panel panel(g < std::size(law_groups) ? law_groups[g].title : "Other laws", "voidage ε [–]",
                        g > 0 ? ""
                              : "F = β d_p^2/(18 μ_f (1 − ε))  [–]:  drag / Stokes drag at the superficial slip\n"
                                "β for classical buoyancy −(1 − ε) ρ_f g  (codes with −(1 − ε)∇p use ε β)");
      panel.log_y = true;
      panel.xrange = plot::range(plotted_voidage_min, 1);
      panel.yrange = s.yrange;
      panel.key = "below left Left reverse maxrows 12 font ',10'";
      panel.commands = {"set format y '%g'"};
      if (richardson_zaki) {
        char text[120];
        std::snprintf(text, sizeof text, "set arrow from %.4f, graph 0 to %.4f, graph 1 nohead dt 3 lw 1.5 lc 'black'",
                      *richardson_zaki, *richardson_zaki);
        panel.commands.push_back(text);
        std::snprintf(text, sizeof text,
                      "set label 'Richardson–Zaki ε = %.3f' at %.4f, graph 0.03 rotate by 90 offset -0.6,0 font ',10'",
                      *richardson_zaki, *richardson_zaki);
        panel.commands.push_back(text);
      }
      panels.push_back(std::move(panel));
    }
    return panels[group];
  };
  for (const AnyDragLaw& law : drag::all_drag_laws) {
    const std::string_view name = drag::name_of(law);
    if (name == "Lewis") continue;  // WenYuGidaspow's numbers, checked in main()
    std::size_t group = std::size(law_groups);
    for (std::size_t g = 0; g < std::size(law_groups); ++g)
      if (std::find(law_groups[g].laws.begin(), law_groups[g].laws.end(), name) != law_groups[g].laws.end()) group = g;
    add_law(panel_for(group), law, drawn[group]++, s);
  }
  for (plot::Panel& panel : panels) {
    panel.add("buoyant weight (ρ_p − ρ_f) g d_p^2 ε/(18 μ_f u_s)", "lines lw 1.5 lc 'black'")
        .point(plotted_voidage_min, weight_line(s, plotted_voidage_min))
        .point(1, weight_line(s, 1));
    panel.add_legend("thin dotted: outside the law's declared validity [ε, Re]", "lines lw 1.2 dt (2,3) lc 'black'");
    panel.add_legend("large marker: curve meets weight, homogeneous bed ε_{eq} (eq. 3.28)", "points pt 6 ps 2 lc 'black'");
  }
  return panels;
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
    const double re = reynolds_of(s);
    const std::optional<double> rz =
        fluidization::richardson_zaki_equilibrium_voidage(s.superficial_velocity, s.fluid, s.particles);
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
      const std::optional<double> eq =
          fluidization::equilibrium_voidage(law, s.superficial_velocity, s.fluid, s.particles);
      if (eq)
        std::printf("   %.4f\n", *eq);
      else
        std::printf("   no bed\n");
      if (eq && !meets_weight_line(law, s, *eq)) {
        ++failures;
        std::printf("  FAIL: F(eps_eq) = %.9g differs from the weight line's %.9g\n", dimensionless_force(law, s, *eq),
                    weight_line(s, *eq));
      }
      if (name == "MazzeiLettieri") {
        const bool ok = eq && rz && std::abs(*eq / *rz - 1) <= 1e-9;
        failures += !ok;
        if (!ok) std::printf("  FAIL: Mazzei-Lettieri's equilibrium voidage differs from Richardson-Zaki's\n");
      }
    }
    const AnyDragLaw lewis = drag::make_drag_law("Lewis"), gidaspow_wen_yu = drag::make_drag_law("WenYuGidaspow");
    double lewis_apart = 0;
    for (double e : plotted_voidages())
      lewis_apart =
          std::max(lewis_apart, std::abs(dimensionless_force(lewis, s, e) / dimensionless_force(gidaspow_wen_yu, s, e) - 1));
    failures += !(lewis_apart <= 1e-15);
    std::printf("  every eps_eq: F meets the weight line there (the plot's markers); |Lewis/WenYuGidaspow - 1| = "
                "%.1e over the plotted eps (<= 1e-15)%s\n\n",
                lewis_apart, lewis_apart <= 1e-15 ? "" : "   FAIL");
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
    const double expected_ratio[] = {0.8886, 0.9422, 0.9472, 0.5772, 0.2679};
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
      const bool ok = identities && std::abs(ratio - expected_ratio[i]) <= 6e-5;
      failures += !ok;
      std::printf(
          "  Re %-6g WenYu/Ergun = %.5f (eqs. 45-46: %.4f); switched = Ergun below, WenYu at 0.8; blend = mean: %s%s\n",
          reynolds[i], ratio, expected_ratio[i], identities ? "yes" : "NO", ok ? "" : "   FAIL");
    }
  }

  std::printf(
      "\nSeed 000 eq. 4.5: Ergun u_mf at eps = 0.4, FCC 137 um / 1210 kg/m3 in air (rho_f 1.18, mu_f 1.81e-5)\n");
  {
    const Fluid<double> air{1.18, 1.81e-5};
    const Particles<double> fcc{1210.0, 137e-6};
    const double u_mf = fluidization::ErgunMinimumFluidization{0.4}(air, fcc);
    const std::optional<double> eq = fluidization::equilibrium_voidage(drag::Ergun{}, 8.73e-3, air, fcc);
    const bool ok = std::abs(u_mf - 8.73e-3) <= 0.005e-3 && eq && std::abs(*eq - 0.4) <= 5e-4;
    failures += !ok;
    std::printf(
        "  u_mf = %.5e m/s (thesis 8.73e-3); Ergun drag at u_s = 8.73e-3 m/s balances the weight at eps = %.5f%s\n",
        u_mf, eq ? *eq : -1.0, ok ? "" : "   FAIL");
  }

  if (directory) {
    for (const System& s : systems) {
      char title[200];
      std::snprintf(title, sizeof title,
                    "Every drag law of the library against ε: %s; Re = ρ_f u_s d_p/μ_f = %.3g along every curve",
                    s.name, reynolds_of(s));
      const std::string png = plot::render(
          *directory, s.file,
          panels_of(s, fluidization::richardson_zaki_equilibrium_voidage(s.superficial_velocity, s.fluid, s.particles)),
          {title, 0, 640, 860});
      if (!png.empty()) std::printf("plotted %s\n", png.c_str());
    }
  } else {
    std::printf("\n(no output directory given: no plot)\n");
  }
  if (failures) std::printf("%d checks FAILED\n", failures);
  return failures == 0 ? 0 : 1;
}
