// How many digits a Gauss rule has: the error estimate of invert() (moments/accuracy.hpp) against
// the measured error, N = 2 … 10 nodes, in double and float.
//
// Cells, in SI units (diameters in metres, number densities in m⁻³), 120 per set, N and type:
//   atoms      N atoms, diameters log-normal around 100 µm (σ_ln 0.45), number densities
//              uniform over 5e7–1.05e9 m⁻³;
//   lognormal  log-normal number distributions, median 20–500 µm, σ_ln 0.15–0.6, n = 1e9–1e12 m⁻³:
//              m_k = n exp(k μ + k² σ²/2).
// The moments are formed in 50 digits and rounded to the type; the measured error is that of the
// type's invert() against a 50-digit invert() of the same rounded moments (the largest relative
// node or weight error), for the cells both call ok and whose estimate is below 0.01 (beyond, first
// order only says that few or no digits are left, not how far off the rule is).
//
// The program fails if an estimate is below a hundredth of the measured error, or if fewer than
// 85 % of the cells have their estimate within a factor 10 of it. The plot
// (inversion_error_estimate.png): estimate against measured error, one panel per type.
//
//   inversion_error_estimate [output directory for the plot; none: no plot]
#include <algorithm>
#include <array>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fluidbed/moments/inversion.hpp"
#include "plot.hpp"

namespace {

using fluidbed::moments::InversionOptions;
using fluidbed::moments::InversionResult;
using fluidbed::moments::InversionStatus;
using fluidbed::moments::invert;
using Exact = boost::multiprecision::cpp_bin_float_50;

constexpr int max_nodes = 10;
constexpr int cells_per_row = 120;

enum class Cells { atoms, lognormal };
const char* name(Cells set) { return set == Cells::atoms ? "atoms" : "lognormal"; }

// 2N moments of a random cell of the set, in 50 digits.
template <int N>
std::array<Exact, 2 * N> random_cell(Cells set, std::mt19937_64& random) {
  std::uniform_real_distribution<double> uniform(0, 1);
  std::array<Exact, 2 * N> m;
  if (set == Cells::atoms) {
    std::lognormal_distribution<double> diameter(std::log(100e-6), 0.45);
    std::array<Exact, N> x, w;
    for (int i = 0; i < N; ++i) {
      x[i] = diameter(random);
      w[i] = 1e9 * (0.05 + uniform(random));
    }
    for (int k = 0; k < 2 * N; ++k) {
      m[k] = 0;
      for (int i = 0; i < N; ++i) m[k] += w[i] * pow(x[i], k);
    }
  } else {
    const Exact mu = log(Exact(20e-6) * pow(Exact(25), Exact(uniform(random))));
    const Exact sigma = 0.15 + 0.45 * uniform(random);
    const Exact number = pow(Exact(10), Exact(9 + 3 * uniform(random)));
    for (int k = 0; k < 2 * N; ++k) m[k] = number * exp(k * mu + k * k * sigma * sigma / 2);
  }
  return m;
}

struct Sample {
  double estimate, measured;
};

// The largest relative difference of the nodes and weights of two rules of n nodes.
template <class A, class B, int N>
double rule_difference(const fluidbed::moments::Quadrature<A, N>& a, const fluidbed::moments::Quadrature<B, N>& b) {
  Exact worst = 0;
  for (int i = 0; i < a.size; ++i) {
    worst = std::max(worst, Exact(abs(Exact(a.nodes[i]) - Exact(b.nodes[i])) / abs(Exact(b.nodes[i]))));
    worst = std::max(worst, Exact(abs(Exact(a.weights[i]) - Exact(b.weights[i])) / abs(Exact(b.weights[i]))));
  }
  return double(worst);
}

template <class T, int N>
std::vector<Sample> samples(Cells set, std::mt19937_64& random, int& skipped) {
  std::vector<Sample> out;
  for (int c = 0; c < cells_per_row; ++c) {
    const std::array<Exact, 2 * N> exact = random_cell<N>(set, random);
    std::array<T, 2 * N> m;
    std::array<Exact, 2 * N> rounded;
    for (int k = 0; k < 2 * N; ++k) rounded[k] = m[k] = T(exact[k]);
    const InversionResult<T, N> r = invert<N>(m, InversionOptions{.estimate_error = true});
    const InversionResult<Exact, N> reference = invert<N>(rounded);
    const double estimate = std::max(double(r.error.nodes), double(r.error.weights));
    if (r.status != InversionStatus::ok || reference.status != InversionStatus::ok || !(estimate <= 0.01)) {
      ++skipped;
      continue;
    }
    out.push_back({estimate, std::max(rule_difference(r.quadrature, reference.quadrature), 1e-300)});
  }
  return out;
}

struct Tally {
  int cells = 0, within = 0;
  double lowest = 1e300;  // the smallest estimate/measured
  void add(const std::vector<Sample>& s) {
    for (const Sample& x : s) {
      const double ratio = x.estimate / x.measured;
      ++cells;
      within += ratio >= 0.1 && ratio <= 10;
      lowest = std::min(lowest, ratio);
    }
  }
};

template <class T, int... Index>
void run_type(const char* type, plot::Panel& panel, Tally& total, std::integer_sequence<int, Index...>) {
  std::mt19937_64 random(20261128);
  std::printf("%s\n  %-10s %3s %6s %8s %14s %16s %10s\n", type, "cells", "N", "used", "skipped",
              "within 10x [%]", "lowest est/meas", "median");
  int curve = 0;
  for (Cells set : {Cells::atoms, Cells::lognormal}) {
    plot::Series& points = panel.add(std::string(name(set)) + " cells", "points " + plot::look(curve++).marker(0.6));
    const auto row = [&]<int N>() {
      int skipped = 0;
      const std::vector<Sample> s = samples<T, N>(set, random, skipped);
      Tally t;
      t.add(s);
      total.add(s);
      std::vector<double> ratios;
      for (const Sample& x : s) {
        ratios.push_back(x.estimate / x.measured);
        points.point(x.measured, x.estimate);
      }
      std::sort(ratios.begin(), ratios.end());
      if (ratios.empty()) {
        std::printf("  %-10s %3d %6d %8d   (no cell with an ok rule and an estimate below 0.01)\n", name(set), N, 0, skipped);
        return;
      }
      std::printf("  %-10s %3d %6d %8d %14.1f %16.3g %10.3g\n", name(set), N, t.cells, skipped,
                  100.0 * t.within / t.cells, t.lowest, ratios[ratios.size() / 2]);
    };
    (row.template operator()<Index + 2>(), ...);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const auto directory = plot::output_directory(argc, argv);
  std::vector<plot::Panel> panels;
  Tally total;
  for (const char* type : {"double", "float"}) {
    plot::Panel& panel = panels.emplace_back(std::string(type) + ": estimate against measured error",
                                             "measured relative error of the rule (against 50 digits)",
                                             "estimated relative error (InversionResult::error)");
    panel.log_x = panel.log_y = true;
    const bool is_double = std::string(type) == "double";
    const std::string span = is_double ? "[1e-17:1]" : "[1e-8:1]";
    panel.xrange = panel.yrange = span;
    panel.key = "top left";
    if (is_double)
      run_type<double>(type, panel, total, std::make_integer_sequence<int, max_nodes - 1>{});
    else
      run_type<float>(type, panel, total, std::make_integer_sequence<int, max_nodes - 1>{});
    panel.add("estimate = measured", "lines lw 2 dt 1 lc rgb '#000000'").point(1e-17, 1e-17).point(1, 1);
    panel.add("10× and 1/10 of it", "lines lw 1 dt (6,4) lc rgb '#000000'")
        .point(1e-18, 1e-17)
        .point(0.1, 1)
        .gap()
        .point(1e-17, 1e-18)
        .point(1, 0.1);
  }
  const double fraction = double(total.within) / total.cells;
  const bool ok = total.lowest >= 0.01 && fraction >= 0.85;
  std::printf("\nall: %d cells, %.1f %% with the estimate within a factor 10 of the measured error (>= 85 %% "
              "required),\n     lowest estimate/measured %.3g (>= 0.01 required)%s\n",
              total.cells, 100 * fraction, total.lowest, ok ? "" : "   FAIL");
  if (directory) {
    const std::string png = plot::render(*directory, "inversion_error_estimate", panels,
                                         {"Gauss rules of 2–10 nodes, random atom and log-normal cells: "
                                          "estimated against measured error",
                                          2, 640, 600});
    if (!png.empty()) std::printf("plotted %s\n", png.c_str());
  }
  return ok ? 0 : 1;
}
