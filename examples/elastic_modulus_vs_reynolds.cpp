// The voidage exponent ψ_e and the elastic modulus of the Mazzei–Lettieri closures against the
// Reynolds number, parametric in ε: seed 000 (Mazzei, PhD thesis, UCL 2008). Plots:
//
//   psi_e_mazzei_lettieri.png   ψ_e(ε, Re) = −ln φ_ML/ln ε (eq. 3.64; φ_ML is the thesis's
//             voidage function φ of eq. 3.57, Table 3.1, renamed because φ is the solids fraction
//             here) against Re = ρ_f ε w d/μ_f, for ε = 0.40, 0.50, 0.60, 0.70, 0.80, 0.90, 0.95,
//             with each curve's minimum, Di Felice's α_d(Re) (eq. 3.48) and Wen & Yu's α = 2.70.
//             The thesis's Fig. 3.4 plots this quantity with measurements (Happel & Epstein
//             1954, Rumpf & Gupte 1971) for an ε family it does not list; the figure is missing
//             from the seed, so these are model curves only, not a reproduction of it.
//   equivalent_exponents.png    ψ_e beside the "equivalent exponent" of Ergun (eq. 3.32 equated
//             to eq. 3.65), α_d(Re) and α = 2.70, at ε = 0.40 and 0.80 (twice: on the scale of
//             the other laws and on Ergun's, which reaches 8.7): the model curves of the
//             thesis's Fig. 3.6, without its measurements.
//   elastic_modulus_ratio.png   the equilibrium elastic modulus E_r^e (eq. 3.111) over Jean–Fan's
//             E_j (eq. 3.95), i.e. H(ε, Re_t)/(−4.8/ε) (eqs. 3.109, 4.38), against Re_t (= Re* at
//             equilibrium): eq. 3.112 states only its limits.
//
// What the thesis states (§3.4.4.3, §3.4.5, §3.5.3), compared:
//   ψ_e → 2.80 as Re → 0 and Re → ∞ (eqs. 3.68, 3.71)                   |ψ_e − 2.80| <= 0.005
//       at Re = 1e-10 and 1e14 (the approach is slow, ∝ Re^½ and Re^−¾)
//   "in the intermediate region it drops significantly reaching values as low as 1.90"
//       min over Re and the ε family                                       1.90 ± 0.02
//   "the minimum ... is an increasing function of ε varying roughly between 1.90 and 2.30"
//       min_Re ψ_e increasing in ε; at ε = 0.95                            2.30 ± 0.02
//   α_d(Re) → 2.7 at both ends; "a minimum value of about 2.1 in correspondence of a value of
//       Re of roughly 28" (one decimal: ± 0.05; "roughly": Re within ± 20 %)
//   E_r^e → E_j as Re_t → 0 and Re_t → ∞ (eq. 3.112; H → −4.80/ε, eq. 4.38)
//       at Re_t = 1e-12 and 1e14                                           |E_r^e/E_j − 1| <= 1e-3
//
//   elastic_modulus_vs_reynolds [output directory for the plots; none: no plots]
//
// Exits non-zero if a comparison fails.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "fluidbed/drag/di_felice.hpp"
#include "fluidbed/drag/ergun.hpp"
#include "fluidbed/drag/mazzei_lettieri.hpp"
#include "fluidbed/elastic/elastic_modulus.hpp"
#include "fluidbed/fluidization/bed_expansion.hpp"
#include "plot.hpp"

namespace {

constexpr double voidages[] = {0.40, 0.50, 0.60, 0.70, 0.80, 0.90, 0.95};
constexpr int voidage_count = int(std::size(voidages));

double psi_e(double voidage, double re) { return fluidbed::drag::MazzeiLettieri::equivalent_exponent(voidage, re); }

// α_d of eq. 3.48: Di Felice's χ(Re) − 1 (χ is his exponent in the pressure-gradient convention).
double alpha_d(double re) { return fluidbed::drag::DiFelice<>::exponent(re) - 1.0; }

// E_r^e/E_j = H(ε, Re_t)/(−4.8/ε).
double modulus_ratio(double voidage, double re_t) {
  using namespace fluidbed::elastic;
  return voidage_sensitivity(MazzeiLettieriModulus{}, voidage, re_t) / voidage_sensitivity(JeanFanModulus{}, voidage, re_t);
}

struct Minimum {
  double value, reynolds;
};

// The minimum of f over log-spaced Re in [1e-2, 1e5] (100 points per decade), refined by a
// golden-section search in log Re around the best grid point.
template <class F>
Minimum minimum_over_reynolds(F f) {
  int best = 0;
  double best_value = f(1e-2);
  for (int i = 1; i <= 700; ++i) {
    const double v = f(std::pow(10.0, -2 + i / 100.0));
    if (v < best_value) best_value = v, best = i;
  }
  double a = -2 + (best - 1) / 100.0, b = -2 + (best + 1) / 100.0;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int k = 0; k < 60; ++k) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (f(std::pow(10.0, c)) < f(std::pow(10.0, d)))
      b = d;
    else
      a = c;
  }
  const double x = std::pow(10.0, (a + b) / 2);
  return {f(x), x};
}

std::string voidage_label(double e) {
  char text[32];
  std::snprintf(text, sizeof text, "ε = %.2f", e);
  return text;
}

std::vector<double> log_grid(double from, double to, int per_decade) {
  std::vector<double> x;
  const int n = int(std::lround(std::log10(to / from) * per_decade));
  for (int i = 0; i <= n; ++i) x.push_back(from * std::pow(10.0, double(i) / per_decade));
  return x;
}

// ψ_e of eq. 3.64 with the symbol the thesis uses for the voidage function (φ there) renamed: in
// the library φ is the solids fraction 1 − ε.
const char* const psi_e_label =
    "ψ_e = −ln φ_{ML} / ln ε  [–]\nφ_{ML}: voidage function of eq. 3.57 (not the solids fraction 1 − ε)";
const char* const reynolds_label = "Re = ρ_f ε |u_f − v_p| d_p / μ_f  [–]";
constexpr int markers_every = 24;  // samples between two markers of a curve (40 per decade)

std::string plot_psi_e(const std::string& directory, const std::vector<Minimum>& minima) {
  plot::Panel panel("Voidage exponent ψ_e(ε, Re) of the Mazzei–Lettieri drag (eq. 3.64): model curves",
                    reynolds_label, psi_e_label);
  panel.log_x = true;
  panel.xrange = "[1e-3:1e5]";
  panel.yrange = "[1.8:3.0]";
  panel.key = "bottom right font ',10'";
  panel.commands = {
      "set arrow from 1e-3, 1.90 to 1e5, 1.90 nohead lw 1 dt 3 lc 'gray30'",
      "set arrow from 1e-3, 2.30 to 1e5, 2.30 nohead lw 1 dt 3 lc 'gray30'",
      "set label 'Mazzei (2008) §3.4.5: minima from 1.90 (dense) …' at 1.5e-3, 1.875 font ',10'",
      "set label '… to 2.30 (dilute)' at 1.5e-3, 2.275 font ',10'",
  };
  const std::vector<double> re = log_grid(1e-3, 1e5, 40);
  for (int e = 0; e < voidage_count; ++e) {
    plot::Series& s = panel.add(voidage_label(voidages[e]), plot::look(e), markers_every, 3 * e);
    for (double r : re) s.point(r, psi_e(voidages[e], r));
  }
  plot::Series& lows = panel.add("minimum over Re of each curve", "points pt 2 ps 2 lw 2 lc 'black'");
  for (const Minimum& m : minima) lows.point(m.reynolds, m.value);
  plot::Series& d = panel.add("Di Felice α_d(Re) = χ − 1 (3.48)", "lines lw 2.5 dt (6,3) lc 'gray50'");
  for (double r : re) d.point(r, alpha_d(r));
  panel.add("Wen & Yu α = 2.70", "lines lw 1.5 dt (2,2) lc 'gray50'").point(1e-3, 2.7).point(1e5, 2.7);
  panel.add("limit 2.80 (3.68, 3.71)", "lines lw 1 lc 'black'").point(1e-3, 2.8).point(1e5, 2.8);
  return plot::render(directory, "psi_e_mazzei_lettieri", {panel});
}

std::string plot_equivalent_exponents(const std::string& directory) {
  struct View {
    double voidage;
    const char* yrange;
    const char* title;
    const char* note;
  };
  // Ergun's exponent at ε = 0.80 climbs to 8.7: the third panel shows it on its own scale.
  const View views[] = {
      {0.40, "[1.8:3.0]", "ε = 0.40", ""},
      {0.80, "[1.8:3.0]", "ε = 0.80", "Ergun leaves this scale above 3.0: see the right-hand panel"},
      {0.80, "[1.5:9.5]", "ε = 0.80, scaled to Ergun's maximum (8.7)", ""}};
  std::vector<plot::Panel> panels;
  const std::vector<double> re = log_grid(1e-3, 1e5, 40);
  for (const View& v : views) {
    plot::Panel panel(v.title, reynolds_label, "voidage exponent ψ of the law [–]");
    panel.log_x = true;
    panel.xrange = "[1e-3:1e5]";
    panel.yrange = v.yrange;
    panel.key = "below left Left reverse font ',10'";
    if (*v.note) panel.commands = {std::string("set label '") + v.note + "' at graph 0.03, graph 0.96 font ',10'"};
    plot::Series& ml = panel.add("Mazzei–Lettieri ψ_e (3.64)", plot::look(0), markers_every, 0);
    for (double r : re) ml.point(r, psi_e(v.voidage, r));
    plot::Series& er = panel.add("Ergun: the ψ that makes (3.65) equal (3.32)", plot::look(1), markers_every, 8);
    for (double r : re)
      er.point(r, fluidbed::fluidization::equivalent_exponent(fluidbed::drag::Ergun{}, v.voidage, r));
    plot::Series& df = panel.add("Di Felice α_d(Re) = χ − 1 (3.48)", plot::look(2), markers_every, 16);
    for (double r : re) df.point(r, alpha_d(r));
    panel.add("Wen & Yu α = 2.70", "lines lw 2 dt (2,2) lc 'black'").point(1e-3, 2.7).point(1e5, 2.7);
    panels.push_back(panel);
  }
  return plot::render(directory, "equivalent_exponents", panels,
                      {"Voidage exponent ψ of four drag laws against Re (β_{classical} = ¾ C_D ρ_f w (1 − ε) ε^{−ψ}/d_p, "
                       "Dallavalle C_D): model curves",
                       0, 620, 560});
}

std::string plot_modulus(const std::string& directory) {
  plot::Panel panel("Equilibrium elastic modulus of Mazzei–Lettieri over Jean–Fan's (eqs. 3.111, 3.95, 3.112)",
                    "Re_t = ρ_f u_t d_p / μ_f  [–]  (= Re^* at equilibrium)",
                    "E_r^e / E_j = H(ε, Re_t) / (−4.8/ε)  [–]");
  panel.log_x = true;
  panel.xrange = "[1e-4:1e8]";
  panel.key = "bottom left font ',10'";
  const std::vector<double> re = log_grid(1e-4, 1e8, 30);
  for (int e = 0; e < voidage_count; ++e) {
    plot::Series& s = panel.add(voidage_label(voidages[e]), plot::look(e), 20, 3 * e);
    for (double r : re) s.point(r, modulus_ratio(voidages[e], r));
  }
  panel.add("limit 1 (3.112)", "lines lw 1 dt 2 lc 'black'").point(1e-4, 1).point(1e8, 1);
  return plot::render(directory, "elastic_modulus_ratio", {panel});
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<std::string> directory = plot::output_directory(argc, argv);
  std::printf(
      "Seed 000: psi_e(eps, Re) = -ln phi_ML/ln eps of the Mazzei-Lettieri drag (eq. 3.64; phi_ML the voidage\n"
      "function of eq. 3.57, Table 3.1; the quantity of the thesis's Fig. 3.4), and the equilibrium elastic modulus\n"
      "E_r^e (3.111) over Jean-Fan's E_j (3.95) against Re_t (eq. 3.112).\n\n");

  const double table_re[] = {1e-4, 1e-2, 1, 10, 100, 1e3, 1e4, 1e6};
  std::printf("psi_e(eps, Re)\n  eps  |");
  for (double re : table_re) std::printf(" Re=%-6.0e", re);
  std::printf(" | min psi_e  at Re\n");
  std::vector<Minimum> minima;
  for (double e : voidages) {
    std::printf("  %.2f |", e);
    for (double re : table_re) std::printf(" %9.4f", psi_e(e, re));
    const Minimum m = minimum_over_reynolds([e](double re) { return psi_e(e, re); });
    minima.push_back(m);
    std::printf(" |   %.4f  %6.1f\n", m.value, m.reynolds);
  }
  std::printf("  alpha_d of Di Felice (3.48):");
  for (double re : table_re) std::printf(" %.4f", alpha_d(re));
  std::printf("\n\n");

  const double table_re_t[] = {1e-12, 1e-3, 1, 10, 100, 1e4, 1e8, 1e14};
  std::printf("E_r^e/E_j = H(eps, Re_t)/(-4.8/eps)\n  eps  |");
  for (double re : table_re_t) std::printf(" Re_t=%-5.0e", re);
  std::printf("\n");
  for (double e : voidages) {
    std::printf("  %.2f |", e);
    for (double re : table_re_t) std::printf(" %10.5f", modulus_ratio(e, re));
    std::printf("\n");
  }
  std::printf("\n");

  int failures = 0;
  auto check = [&](const char* what, const char* thesis, bool ok, const std::string& here) {
    failures += !ok;
    std::printf("  %-46s thesis %-14s here %s%s\n", what, thesis, here.c_str(), ok ? "" : "   FAIL");
  };
  char text[200];
  std::printf("Thesis statements against the library:\n");
  {
    double worst = 0;
    for (double e : voidages)
      for (double re : {1e-10, 1e14}) worst = std::max(worst, std::abs(psi_e(e, re) - 2.8));
    std::snprintf(text, sizeof text, "max |psi_e - 2.80| = %.4f at Re = 1e-10 and 1e14 (<= 0.005)", worst);
    check("psi_e limits (3.68, 3.71)", "2.80", worst <= 0.005, text);
  }
  {
    const Minimum& lowest = *std::min_element(minima.begin(), minima.end(),
                                              [](const Minimum& a, const Minimum& b) { return a.value < b.value; });
    std::snprintf(text, sizeof text, "%.4f (eps %.2f, Re %.1f) (+-0.02)", lowest.value,
                  voidages[&lowest - minima.data()], lowest.reynolds);
    check("lowest psi_e", "1.90", std::abs(lowest.value - 1.90) <= 0.02, text);
    bool increasing = true;
    for (int e = 1; e < voidage_count; ++e) increasing = increasing && minima[e].value > minima[e - 1].value;
    std::snprintf(text, sizeof text, "%.4f at eps 0.40 ... %.4f at eps 0.95, %s", minima.front().value,
                  minima.back().value, increasing ? "increasing" : "NOT increasing");
    check("min_Re psi_e: increasing in eps, 1.90 .. 2.30", "1.90 .. 2.30",
          increasing && std::abs(minima.front().value - 1.90) <= 0.02 && std::abs(minima.back().value - 2.30) <= 0.02,
          text);
  }
  {
    const Minimum m = minimum_over_reynolds(alpha_d);
    std::snprintf(text, sizeof text, "%.4f at Re %.2f (exactly 2.05 at 10^1.5) (+-0.05, Re +-20 %%)", m.value,
                  m.reynolds);
    check("Di Felice alpha_d minimum", "2.1 at Re 28",
          std::abs(m.value - 2.1) <= 0.05 && std::abs(m.reynolds / 28 - 1) <= 0.2, text);
    const double low = alpha_d(1e-8), high = alpha_d(1e12);
    std::snprintf(text, sizeof text, "%.4f at Re 1e-8, %.4f at Re 1e12 (+-0.005)", low, high);
    check("Di Felice alpha_d limits", "2.7", std::abs(low - 2.7) <= 0.005 && std::abs(high - 2.7) <= 0.005, text);
  }
  {
    double worst = 0;
    for (double e : voidages)
      for (double re : {1e-12, 1e14}) worst = std::max(worst, std::abs(modulus_ratio(e, re) - 1));
    std::snprintf(text, sizeof text, "max |E_r^e/E_j - 1| = %.1e at Re_t = 1e-12 and 1e14 (<= 1e-3)", worst);
    check("E_r^e -> E_j in both limits (3.112)", "1", worst <= 1e-3, text);
  }
  {
    const Minimum dip_dense = minimum_over_reynolds([](double re) { return modulus_ratio(0.40, re); });
    const Minimum dip_dilute = minimum_over_reynolds([](double re) { return modulus_ratio(0.95, re); });
    const Minimum peak_modulus = minimum_over_reynolds([](double re) { return -modulus_ratio(0.95, re); });
    const Minimum peak_psi = minimum_over_reynolds([](double re) { return -psi_e(0.95, re); });
    std::printf(
        "Between the limits E_r^e/E_j is not monotone: it dips to %.3f (eps 0.40, Re_t %.0f) and %.3f (eps 0.95,\n"
        "Re_t %.0f), so the Mazzei-Lettieri modulus is below Jean-Fan's in the intermediate regime, and it exceeds 1\n"
        "slightly at low Re_t in dilute beds (%.4f at eps 0.95, Re_t %.2f). psi_e likewise overshoots 2.80 at low Re\n"
        "(%.4f at eps 0.95, Re %.2f). The thesis states only the limits; its figures are not in the seed.\n",
        dip_dense.value, dip_dense.reynolds, dip_dilute.value, dip_dilute.reynolds, -peak_modulus.value,
        peak_modulus.reynolds, -peak_psi.value, peak_psi.reynolds);
  }

  if (directory) {
    for (const std::string& png :
         {plot_psi_e(*directory, minima), plot_equivalent_exponents(*directory), plot_modulus(*directory)})
      if (!png.empty()) std::printf("plotted %s\n", png.c_str());
  } else {
    std::printf("(no output directory given: no plots)\n");
  }
  if (failures) std::printf("%d comparisons FAILED\n", failures);
  return failures == 0 ? 0 : 1;
}
