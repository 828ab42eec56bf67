// Seed 003 (Mazzei, Marchisio & Lettieri), Tables 1 and 2: the VDF moments M_0 … M_7 of powders
// A and B and of their mixture (ε = 0.400) and the two-, three- and four-node quadratures
// printed for them, recomputed by the library beside the published values
// (examples/seed003_tables_1_2.hpp).
//
// Two directions, because the inversion is ill-conditioned and the tables are rounded:
//   forward   the library's moments Σ φ_i s_i^k of each published rule (moments_from_quadrature)
//             against the printed M_k, k = 0 … 2N−1 (the moments a Gauss rule reproduces
//             exactly). Tolerance, from the printed digits alone: the rule was computed from
//             unrounded moments M_k^true with |M_k^true − M_k| <= half a unit of the third
//             significant digit, and its printed nodes and weights are within 0.5 µm and 0.0005
//             of the exact ones, so Σ φ s^k of the printed rule must lie in the interval
//             [Σ (φ − 0.0005)(s − 0.5)^k, Σ (φ + 0.0005)(s + 0.5)^k] shifted by that half unit.
//             The program fails if an interval misses the printed moment, except for the one
//             documented inconsistency below. "used" is |difference|/(allowed half-width).
//   inverse   the library's Gauss rule of the printed (rounded) moments (invert, Wheeler) beside
//             the published rule, for information: a change of a printed moment within its last
//             digit moves the nodes by up to ~60 % (the node range over the 2^(2N) corners of the
//             rounding box is printed for N = 2), and several printed sets are not realizable
//             with three or four nodes at all. Also a round trip: the library's rule of the
//             published rule's own moments must return that rule to relative 1e-9 (not less:
//             for powder A's four close nodes, merely rounding the exact moments to double moves
//             the exact rule by up to 4e-10, 50-digit mpmath).
//
// The documented inconsistency: Table 2's two-node rule (105, 0.332; 304, 0.268) reproduces
// Table 2's M_2 and M_3 only to +0.81 % and +0.94 %, outside the rounding (used 1.04 and 1.18);
// it does reproduce the moments of seed 000 Table 6.3 (M_2 2.85e4, M_3 7.95e6), the thesis's
// version of the same mixed powder, which is checked instead.
//
//   seed003_tables_1_2 [output directory for the plot; none: no plot]
#include "seed003_tables_1_2.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fluidbed/moments.hpp"
#include "plot.hpp"

namespace {

using namespace fluidbed::moments;

// Half a unit of the last printed digit of a value printed to `digits` significant digits.
double half_unit(double printed, int digits) {
  return 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(printed))) - (digits - 1));
}

// The moment of order k of a printed rule, and the interval it spans over the rule's rounding box.
struct RuleMoment {
  double value, low, high;
};

RuleMoment rule_moment(const seed003::Rule& rule, int k) {
  const std::span<const double> nodes(rule.diameters.data(), std::size_t(rule.nodes));
  const std::span<const double> weights(rule.weights.data(), std::size_t(rule.nodes));
  std::array<double, 8> m{};
  moments_from_quadrature(nodes, weights, std::span<double>(m.data(), std::size_t(k + 1)));
  RuleMoment r{m[std::size_t(k)], 0, 0};
  for (int i = 0; i < rule.nodes; ++i) {
    r.low +=
        (rule.weights[i] - seed003::weight_half_unit) * std::pow(rule.diameters[i] - seed003::diameter_half_unit, k);
    r.high +=
        (rule.weights[i] + seed003::weight_half_unit) * std::pow(rule.diameters[i] + seed003::diameter_half_unit, k);
  }
  return r;
}

struct Comparison {
  double relative;  // Σ φ s^k / M_k − 1
  double used;      // |difference| / (half-width of the rule's interval + half unit of M_k)
  bool consistent;  // the two intervals overlap
};

Comparison compare(const seed003::Rule& rule, int k, double printed) {
  const RuleMoment r = rule_moment(rule, k);
  const double h = half_unit(printed, seed003::moment_significant_digits);
  return {r.value / printed - 1, std::abs(r.value - printed) / ((r.high - r.low) / 2 + h),
          r.high >= printed - h && r.low <= printed + h};
}

std::string rule_text(std::span<const double> nodes, std::span<const double> weights, const char* node_format) {
  std::string text;
  char item[64];
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    std::snprintf(item, sizeof item, node_format, nodes[i], weights[i]);
    text += item;
  }
  return text;
}

const char* status_name(InversionStatus s) {
  switch (s) {
    case InversionStatus::ok:
      return "ok";
    case InversionStatus::reduced:
      return "reduced";
    case InversionStatus::zero_mass:
      return "zero mass";
    case InversionStatus::not_realizable:
      return "not realizable";
    case InversionStatus::invalid_input:
      return "invalid input";
    case InversionStatus::eigen_failure:
      return "eigen failure";
  }
  return "?";
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<std::string> directory = plot::output_directory(argc, argv);
  std::printf(
      "Seed 003 Tables 1-2: VDF moments (eps = 0.400) and published PD quadratures, against the library.\n"
      "forward: library moments of the published rule vs the printed M_k; 'used' = |difference| / rounding allowance\n"
      "(0.5 um on nodes, 0.0005 on weights, half a unit of the 3rd significant digit of M_k); <= 1 is consistent.\n\n");
  int failures = 0;
  double worst_used = 0;
  std::vector<plot::Panel> panels;
  for (std::size_t p = 0; p < seed003::tables_1_2.size(); ++p) {
    const seed003::Powder& powder = seed003::tables_1_2[p];
    const bool mixture = p == seed003::mixed_powder;
    std::printf("%s: printed M_0 ... M_7 =", powder.name);
    for (double m : powder.moments) std::printf(" %.3g", m);
    std::printf("\n");
    for (const seed003::Rule& rule : powder.rules) {
      const int n = rule.nodes;
      const std::span<const double> nodes(rule.diameters.data(), std::size_t(n));
      const std::span<const double> weights(rule.weights.data(), std::size_t(n));
      const bool documented_exception = mixture && n == 2;
      std::printf("  N = %d published: %s\n", n, rule_text(nodes, weights, " (%.0f um, %.3f)").c_str());
      std::printf("    k  printed M_k   library sum(phi s^k)   rel. diff   used\n");
      bool consistent = true;
      for (int k = 0; k < 2 * n; ++k) {
        const Comparison c = compare(rule, k, powder.moments[std::size_t(k)]);
        consistent = consistent && c.consistent;
        if (!documented_exception) worst_used = std::max(worst_used, c.used);
        std::printf("    %d  %10.3e   %20.6e   %+8.3f %%   %4.2f%s\n", k, powder.moments[std::size_t(k)],
                    rule_moment(rule, k).value, 100 * c.relative, c.used,
                    c.consistent ? "" : (documented_exception ? "  outside (documented)" : "  OUTSIDE"));
      }
      if (documented_exception) {
        // Seed 000 Table 6.3 instead: both the seed 003 rule and the thesis's own (0.331/0.269).
        bool thesis_consistent = true;
        std::printf("    against seed 000 Table 6.3 (M_0 0.600, M_2 2.85e4, M_3 7.95e6; M_1 blank):\n");
        for (const seed003::Rule& r : {rule, seed003::seed000_table_6_3_rule})
          for (const seed003::PartialMoments& m : seed003::seed000_table_6_3_moments) {
            const Comparison c = compare(r, m.order, m.value);
            thesis_consistent = thesis_consistent && c.consistent;
            std::printf("      rule %.3f/%.3f  k = %d: %+8.3f %%  used %4.2f%s\n", r.weights[0], r.weights[1], m.order,
                        100 * c.relative, c.used, c.consistent ? "" : "  OUTSIDE");
          }
        failures += !thesis_consistent;
        std::printf("    -> Table 2's own M_2, M_3 are %s with this rule; seed 000 Table 6.3's are %s\n",
                    consistent ? "consistent" : "INCONSISTENT",
                    thesis_consistent ? "consistent" : "INCONSISTENT (FAIL)");
      } else {
        failures += !consistent;
      }

      // Inverse: the library's rule of the printed moments.
      const std::span<const double> printed(powder.moments.data(), std::size_t(2 * n));
      const auto inverted = invert<double, 4>(printed);
      if (inverted.status == InversionStatus::ok) {
        std::string diffs;
        char item[48];
        for (int i = 0; i < n; ++i) {
          std::snprintf(item, sizeof item, " %+.1f%%/%+.1f%%",
                        100 * (inverted.quadrature.nodes[i] / rule.diameters[i] - 1),
                        100 * (inverted.quadrature.weights[i] / rule.weights[i] - 1));
          diffs += item;
        }
        std::printf(
            "    library's rule of the printed M_0..M_%d: %s\n      (node/weight vs published:%s)\n", 2 * n - 1,
            rule_text(std::span<const double>(inverted.quadrature.nodes.data(), std::size_t(n)),
                      std::span<const double>(inverted.quadrature.weights.data(), std::size_t(n)), " (%.1f um, %.4f)")
                .c_str(),
            diffs.c_str());
      } else {
        std::printf(
            "    library's rule of the printed M_0..M_%d: %s, realizable with %d node(s) only (first failing "
            "Stieltjes\n"
            "      coefficient zeta_%d = %.4g): the printed, rounded set admits no %d-node rule; the published one "
            "came\n"
            "      from the unrounded moments\n",
            2 * n - 1, status_name(inverted.status), inverted.realizable_nodes, inverted.first_failing_index,
            inverted.failing_value, n);
      }
      if (n == 2) {  // conditioning: the nodes over the corners of the rounding box of the printed moments
        double low[2] = {1e300, 1e300}, high[2] = {-1e300, -1e300};
        for (int corner = 0; corner < 16; ++corner) {
          std::array<double, 4> m{};
          for (int k = 0; k < 4; ++k) {
            const double h = half_unit(powder.moments[std::size_t(k)], seed003::moment_significant_digits);
            m[std::size_t(k)] = powder.moments[std::size_t(k)] + ((corner >> k) & 1 ? h : -h);
          }
          const auto r = invert<2>(m);
          if (r.status != InversionStatus::ok) continue;
          for (int i = 0; i < 2; ++i) {
            low[i] = std::min(low[i], r.quadrature.nodes[i]);
            high[i] = std::max(high[i], r.quadrature.nodes[i]);
          }
        }
        std::printf("      over the rounding box of the printed M_0..M_3 the nodes span %.1f-%.1f and %.1f-%.1f um\n",
                    low[0], high[0], low[1], high[1]);
      }
      // Round trip through the library: the published rule's own moments give it back.
      {
        std::array<double, 8> m{};
        moments_from_quadrature(nodes, weights, std::span<double>(m.data(), std::size_t(2 * n)));
        const auto r = invert<double, 4>(std::span<const double>(m.data(), std::size_t(2 * n)));
        double worst = r.status == InversionStatus::ok ? 0.0 : 1.0;
        for (int i = 0; i < n && r.status == InversionStatus::ok; ++i)
          worst = std::max({worst, std::abs(r.quadrature.nodes[i] / rule.diameters[i] - 1),
                            std::abs(r.quadrature.weights[i] / rule.weights[i] - 1)});
        const bool ok = worst <= 1e-9;
        failures += !ok;
        std::printf("    round trip rule -> moments -> rule: max rel. difference %.1e (<= 1e-9)%s\n", worst,
                    ok ? "" : "   FAIL");
      }
    }
    if (powder.sauter_diameter > 0) {
      const double stated = powder.sauter_diameter;
      std::printf("  Sauter diameter sum(phi)/sum(phi/s) of the 2/3/4-node rules:");
      for (const seed003::Rule& rule : powder.rules) {
        double m0 = 0, m_minus_1 = 0;
        for (int i = 0; i < rule.nodes; ++i) m0 += rule.weights[i], m_minus_1 += rule.weights[i] / rule.diameters[i];
        std::printf(" %.2f", m0 / m_minus_1);
      }
      std::printf(
          " um; seed 003 text (sieve data): %.0f um\n      (a Gauss rule does not reproduce M_-1, so these only "
          "approximate it)\n",
          stated);
    }
    std::printf("\n");

    plot::Panel panel(powder.name, "particle diameter s [µm]", "quadrature weight φ_i [–]");
    panel.yrange = "[0:0.7]";
    const seed003::Rule& widest = powder.rules[2];
    panel.xrange = plot::range(std::floor(widest.diameters[0] * 0.8), std::ceil(widest.diameters[3] * 1.15));
    panel.key = "top left";
    const char* colours[3] = {"#0072b2", "#009e73", "#d55e00"};
    for (int r = 0; r < 3; ++r) {
      const seed003::Rule& rule = powder.rules[std::size_t(r)];
      char title[48];
      std::snprintf(title, sizeof title, "%d nodes (published)", rule.nodes);
      plot::Series& s = panel.add(title, std::string("impulses lw 3 lc rgb '") + colours[r] + "'");
      plot::Series& heads = panel.add("", std::string("points pt 7 ps 1.3 lc rgb '") + colours[r] + "'");
      for (int i = 0; i < rule.nodes; ++i) {
        s.point(rule.diameters[i], rule.weights[i]);
        heads.point(rule.diameters[i], rule.weights[i]);
      }
      if (r == 0) {  // the library's two-node rule of the printed moments, for comparison
        const auto inverted = invert<2>(
            std::array<double, 4>{powder.moments[0], powder.moments[1], powder.moments[2], powder.moments[3]});
        plot::Series& lib = panel.add("2 nodes, library, from the printed M_0…M_3", "points pt 6 ps 2 lw 2 lc 'black'");
        for (int i = 0; i < 2; ++i) lib.point(inverted.quadrature.nodes[i], inverted.quadrature.weights[i]);
      }
    }
    panels.push_back(panel);
  }
  std::printf("Forward check: largest 'used' outside the documented exception %.2f (<= 1 required)\n", worst_used);
  if (directory) {
    const std::string png = plot::render(*directory, "seed003_tables_1_2", panels, 560, 460,
                                         "Seed 003 Tables 1–2: published quadratures (impulses) and the library's "
                                         "two-node rule of the printed moments (circles)");
    if (!png.empty()) std::printf("plotted %s\n", png.c_str());
  } else {
    std::printf("(no output directory given: no plot)\n");
  }
  if (failures) std::printf("%d comparisons FAILED\n", failures);
  return failures == 0 ? 0 : 1;
}
