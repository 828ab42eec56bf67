// Moment inversion (QMOM) of two particle size distributions: their volume-density moments
// M_k = ∫ f_v(ξ) ξ^k dξ (seed 000 eq. 5.32, seed 003 eq. 0.7), and the N = 2, 3, 4 node
// Gauss quadratures that fluidbed::moments::invert<N> recovers from M_0 … M_{2N−1} by Wheeler's
// algorithm and by Gordon's product–difference algorithm (seed 000 eqs. 5.86–5.92).
//
//   log-normal   f_v = M_0/(ξ σ √(2π)) exp(−(ln ξ − μ)²/(2 σ²)), M_0 = 0.6 (solids fraction at
//                ε = 0.4), median e^μ = 100 µm, σ = 0.3 (the spread of a narrow Geldart A cut);
//   sieve cut    a Geldart A sieve analysis, apertures 45, 53, 63, 75, 90, 106, 125, 150 µm,
//                mass fractions 0.05, 0.10, 0.20, 0.30, 0.20, 0.10, 0.05, the VDF uniform in each
//                bin (seed 000 eq. E.7 = seed 003 eq. 0.17), ε = 0.4 (an illustrative cut: the
//                seeds give their sieve data only as figures).
//
// The moments are computed in SI units (metres), as a CFD code holds them, and printed in µm.
// Checks (exit status non-zero if one fails):
//   - the quadrature reproduces the moments it was built from: max_k |Σ φ_i ξ_i^k / M_k − 1| over
//     k = 0 … 2N−1 below 1e-12, for both algorithms;
//   - Wheeler and product–difference agree: nodes and weights to 1e-10 relative (not 1e-12: the
//     map from moments to nodes amplifies the rounding of the moments themselves, ~1e-16, by the
//     condition number of the inversion, ~1e5 for four nodes on the narrow sieve cut; the two
//     algorithms then differ by 6e-12, and each differs from the exact rule by ~2e-11);
//   - the nodes and weights equal the independent 50-digit mpmath values of
//     tests/reference/moments_reference.py (cases lognormal_si and sieve_psd: Gauss rules of the
//     measure itself, from the Stieltjes–Wigert recurrence of the log-normal and a Gauss–Legendre
//     discretisation of each sieve bin, never from moment inversion), quoted to 10–12 digits:
//     relative 1e-9.
//
//   quadrature_vs_size_distribution [output directory for the plots; none: no plots]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fluidbed/moments.hpp"
#include "plot.hpp"

namespace {

using namespace fluidbed::moments;

constexpr double micron = 1e-6;
constexpr int max_nodes = 4;
using Moments = std::array<double, 2 * max_nodes + 1>;  // M_0 … M_8 (M_8: the first one no rule matches)

struct Node {
  double diameter_um, weight;
};

// Reference quadratures, tests/reference/moments_reference.py (50-digit mpmath from the measure).
struct Reference {
  int nodes;
  Node values[max_nodes];
};

struct Distribution {
  const char* name;
  const char* title;
  const char* file;
  Moments moments{};             // SI
  std::vector<double> pdf_x_um;  // f_v for the plot
  std::vector<double> pdf_y_um;  // [µm⁻¹]
  std::vector<Reference> references;
};

Distribution lognormal() {
  Distribution d{"log-normal VDF, M_0 = 0.6, median 100 um, sigma = 0.3",
                 "Log-normal volume density (M_0 = 0.6, median 100 µm, σ = 0.3 in ln ξ) and its Gauss quadratures",
                 "quadrature_lognormal",
                 {},
                 {},
                 {},
                 {}};
  const double m0 = 0.6, median = 100 * micron, sigma = 0.3;
  lognormal_moments(m0, LognormalParameters<double>{std::log(median), sigma * sigma}, std::span<double>(d.moments));
  for (int i = 0; i <= 400; ++i) {
    const double x_um = 20 + 0.75 * i;
    const double z = (std::log(x_um * micron) - std::log(median)) / sigma;
    d.pdf_x_um.push_back(x_um);
    d.pdf_y_um.push_back(m0 / (x_um * sigma * std::sqrt(2 * std::numbers::pi)) * std::exp(-0.5 * z * z));
  }
  d.references = {
      {2, {{84.3085669692, 0.428665621879}, {155.377383085, 0.171334378121}}},
      {3, {{73.4578033964, 0.271171282103}, {125.232271619, 0.309998641156}, {213.498377705, 0.0188300767407}}},
      {4,
       {{66.4052736606, 0.171099211733},
        {108.842512156, 0.356667069933},
        {172.507096912, 0.0711596134988},
        {282.750220842, 0.00107410483539}}},
  };
  return d;
}

constexpr double sieve_edges_um[] = {45, 53, 63, 75, 90, 106, 125, 150};
constexpr double sieve_fractions[] = {0.05, 0.10, 0.20, 0.30, 0.20, 0.10, 0.05};

Distribution sieve() {
  Distribution d{
      "sieve analysis 45-150 um (VDF uniform per bin, eq. E.7), eps = 0.4",
      "Sieve analysis 45–150 µm (VDF uniform in each bin, seed 000 eq. E.7, ε = 0.4) and its Gauss quadratures",
      "quadrature_sieve",
      {},
      {},
      {},
      {}};
  const double voidage = 0.4;
  std::array<double, std::size(sieve_edges_um)> edges{};
  for (std::size_t i = 0; i < edges.size(); ++i) edges[i] = sieve_edges_um[i] * micron;
  const SieveAnalysis<double> psd{edges, sieve_fractions};
  sieve_moments(psd, voidage, std::span<double>(d.moments));
  for (std::size_t i = 0; i + 1 < std::size(sieve_edges_um); ++i) {  // the steps of f_v
    const double a = sieve_edges_um[i], b = sieve_edges_um[i + 1], h = (1 - voidage) * sieve_fractions[i] / (b - a);
    d.pdf_x_um.insert(d.pdf_x_um.end(), {a, a, b, b});
    d.pdf_y_um.insert(d.pdf_y_um.end(), {0, h, h, 0});
  }
  d.references = {
      {2, {{68.64569475, 0.3866458202}, {114.1455446, 0.2133541798}}},
      {3, {{58.96296816, 0.1914477368}, {90.33063789, 0.3447659121}, {132.6890202, 0.06378635107}}},
      {4,
       {{53.58427487, 0.1001109769},
        {77.88805191, 0.3078808477},
        {107.151683, 0.1629414408},
        {140.7429108, 0.02906673462}}},
  };
  return d;
}

template <int N>
InversionResult<double, N> quadrature(const Moments& m, RecurrenceAlgorithm algorithm) {
  InversionOptions options;
  options.algorithm = algorithm;
  return invert<double, N>(std::span<const double>(m.data(), 2 * N), options);
}

// max over k < 2N of |Σ φ_i ξ_i^k / M_k − 1|, and the relative error of M_{2N}.
template <int N>
std::pair<double, double> moment_errors(const Quadrature<double, N>& q, const Moments& m) {
  std::array<double, 2 * N + 1> recovered{};
  moments_from_quadrature(q, std::span<double>(recovered));
  double worst = 0;
  for (int k = 0; k < 2 * N; ++k) worst = std::max(worst, std::abs(recovered[k] / m[k] - 1));
  return {worst, recovered[2 * N] / m[2 * N] - 1};
}

struct Outcome {
  int failures = 0;
  std::vector<plot::Panel> panels;
};

template <int N>
void report(const Distribution& d, Outcome& out) {
  const auto wheeler = quadrature<N>(d.moments, RecurrenceAlgorithm::wheeler);
  const auto pd = quadrature<N>(d.moments, RecurrenceAlgorithm::product_difference);
  if (wheeler.status != InversionStatus::ok || pd.status != InversionStatus::ok || wheeler.quadrature.size != N ||
      pd.quadrature.size != N) {
    std::printf("  N = %d: inversion FAILED (status %d / %d)\n", N, int(wheeler.status), int(pd.status));
    ++out.failures;
    return;
  }
  const Reference* reference = nullptr;
  for (const Reference& r : d.references)
    if (r.nodes == N) reference = &r;
  double algorithms_apart = 0, reference_apart = 0;
  std::printf("  N = %d     node [um]      weight      | mpmath reference           | PD - Wheeler (rel.)\n", N);
  for (int i = 0; i < N; ++i) {
    const double x = wheeler.quadrature.nodes[i], w = wheeler.quadrature.weights[i];
    const double dx = pd.quadrature.nodes[i] / x - 1, dw = pd.quadrature.weights[i] / w - 1;
    algorithms_apart = std::max({algorithms_apart, std::abs(dx), std::abs(dw)});
    const Node& r = reference->values[i];
    reference_apart = std::max({reference_apart, std::abs(x / micron / r.diameter_um - 1), std::abs(w / r.weight - 1)});
    std::printf("     %d  %14.9f  %14.11f | %14.9f %14.11f | %9.1e %9.1e\n", i + 1, x / micron, w, r.diameter_um,
                r.weight, dx, dw);
  }
  const auto [wheeler_error, wheeler_next] = moment_errors(wheeler.quadrature, d.moments);
  const auto [pd_error, pd_next] = moment_errors(pd.quadrature, d.moments);
  const bool ok = wheeler_error <= 1e-12 && pd_error <= 1e-12 && algorithms_apart <= 1e-10 && reference_apart <= 1e-9;
  out.failures += !ok;
  std::printf(
      "     max_k<%d |M_k(quadrature)/M_k - 1|: Wheeler %.1e, PD %.1e (<= 1e-12); nodes/weights PD vs Wheeler %.1e\n"
      "     (<= 1e-10), vs mpmath %.1e (<= 1e-9); M_%d, which no %d-node rule matches: %+.2f %%%s\n",
      2 * N, wheeler_error, pd_error, algorithms_apart, reference_apart, 2 * N, N, 100 * wheeler_next,
      ok ? "" : "   FAIL");

  char title[120];
  std::snprintf(title, sizeof title, "N = %d nodes (moments M_0 … M_%d)", N, 2 * N - 1);
  plot::Panel panel(title, "particle diameter ξ [µm]", "volume density f_v(ξ) [µm^{-1}]");
  panel.y2label = "quadrature weight φ_i [–]";
  panel.y2range = "[0:0.5]";
  const double span = d.pdf_x_um.back() - d.pdf_x_um.front();
  panel.xrange = plot::range(d.pdf_x_um.front() - 0.04 * span, d.pdf_x_um.back() + 0.04 * span);
  panel.yrange = plot::range(0, 1.2 * *std::max_element(d.pdf_y_um.begin(), d.pdf_y_um.end()));
  panel.key = "top right";
  plot::Series& pdf = panel.add("f_v(ξ), left axis", "lines lw 2 lc rgb '#0072b2'");
  for (std::size_t i = 0; i < d.pdf_x_um.size(); ++i) pdf.point(d.pdf_x_um[i], d.pdf_y_um[i]);
  plot::Series& spikes = panel.add("nodes ξ_i, weights φ_i, right axis", "impulses lw 4 lc rgb '#d55e00'");
  spikes.axes = "x1y2";
  plot::Series& heads = panel.add("", "points pt 7 ps 1.2 lc rgb '#d55e00'");
  heads.axes = "x1y2";
  for (int i = 0; i < N; ++i) {
    spikes.point(wheeler.quadrature.nodes[i] / micron, wheeler.quadrature.weights[i]);
    heads.point(wheeler.quadrature.nodes[i] / micron, wheeler.quadrature.weights[i]);
  }
  out.panels.push_back(panel);
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<std::string> directory = plot::output_directory(argc, argv);
  int failures = 0;
  for (const Distribution& d : {lognormal(), sieve()}) {
    std::printf("%s\n  moments (SI, shown in um^k):", d.name);
    for (int k = 0; k <= 2 * max_nodes; ++k) std::printf(" M_%d = %.10g", k, d.moments[k] / std::pow(micron, k));
    std::printf("\n  d43 = M_1/M_0 = %.4f um, variance M_2/M_0 - d43^2 = %.4f um^2 (seed 003 eq. 0.21)\n",
                d.moments[1] / d.moments[0] / micron,
                variance(std::span<const double>(d.moments.data(), 3)) / (micron * micron));
    Outcome out;
    report<2>(d, out);
    report<3>(d, out);
    report<4>(d, out);
    failures += out.failures;
    std::printf("\n");
    if (directory) {
      const std::string png = plot::render(*directory, d.file, out.panels, {d.title, 0, 620, 500});
      if (!png.empty()) std::printf("plotted %s\n\n", png.c_str());
    }
  }
  if (!directory) std::printf("(no output directory given: no plots)\n");
  if (failures) std::printf("%d quadratures FAILED\n", failures);
  return failures == 0 ? 0 : 1;
}
