// Two powders mixing by diffusion in a closed column, described by a two-node DQMOM of the whole
// mixture, with and without the diffusion-induced source terms, against the exact solution.
//
// Set-up: the bed of seed 000 (Mazzei, PhD thesis, UCL 2008) §6.3, reduced to one dimension and to
// diffusion alone: two layers of equal height, powder A below (0 <= z < H/2) and powder B above,
// each described by its two-node quadrature of seed 000 Table 6.2 (voidage 0.400):
//   A: 75 µm (φ = 0.262), 103 µm (φ = 0.338);   B: 240 µm (φ = 0.380), 355 µm (φ = 0.220);
// column height H = 0.30 m (the two 15 cm layers), no flux through the bottom and the top, constant
// diffusivity 𝒟 = 2.5e-4 m²/s: the numerical diffusion of first-order upwinding, 𝒟_n = u L_c/2 at
// u = 0.10 m/s and 5 mm cells (seed 000 eq. 6.25, after Ferziger & Perić 2002), which is what mixed
// the thesis's nodes. The results depend on τ = 𝒟t/H² alone: t = 360 s × τ here, 9e4 s × τ at the
// thesis's physical estimate 𝒟_x ≈ 1e-6 m²/s (eq. 6.24, after Gidaspow 1994).
//
// Two-node DQMOM of the mixture (seed 000 §6.5.2): every cell carries two nodes ξ_1 < ξ_2 with their
// volume fractions φ_1, φ_2, initially those of the powder it holds, so at the interface node 1 jumps
// from A's 75 µm to B's 240 µm and node 2 from 103 to 355 µm. Transported are φ_i and φ_iξ_i:
//   ∂φ_i/∂t = 𝒟 ∂²φ_i/∂z² + c_i^φ,   ∂(φ_iξ_i)/∂t = 𝒟 ∂²(φ_iξ_i)/∂z² + c_i^ξ     (seed 000 eqs. 6.20–6.21)
//   (i)   with the diffusion-induced sources (Marchisio & Fox 2005, J. Aerosol Sci. 36, 43–73,
//         doi:10.1016/j.jaerosci.2004.07.009; seed 000 eqs. 6.22–6.23): c solves the DQMOM system
//         (dqmom::solve) for s_k = k(k − 1) Σ_i ξ_i^(k−2) C_i (dqmom::diffusion_sources),
//         C_i = 𝒟 φ_i (∂ξ_i/∂z)²;
//   (ii)  without them (c = 0): the thesis's first simulation, where numerical diffusion mixed the
//         nodes without the sources (seed 000 Table 6.6: nodes 165 and 190 µm instead of 102, 314);
//   (iii) exact: the volume density is f_v(ξ, z, t) = a(z, t) f_A(ξ) + (1 − a) f_B(ξ), with a, the
//         fraction of powder A, diffusing from the step a(z, 0) = 1 (z < H/2), 0 (z > H/2):
//           a = 1/2 + Σ_{n odd} (2/(nπ)) sin(nπ/2) cos(nπz/H) exp(−n²π²τ)      (zero-flux walls),
//         so that every moment M_k = a M_k^A + (1 − a) M_k^B diffuses exactly; their two-node Gauss
//         rule (invert<2> of M_0 … M_3) is what an exact two-node DQMOM carries. Well mixed (a = 1/2)
//         it is seed 000 Table 6.4's theoretical mixture, 102 µm (0.360) and 314 µm (0.240).
//
// Numerics of (i) and (ii): N cells of height Δz = H/N (N even: the interface is a cell face).
//   - Diffusion: the conservative finite-volume Laplacian (u_{j+1} − 2u_j + u_{j−1})/Δz² with zero
//     flux through both walls, integrated exactly in time: its eigenvectors are the discrete cosines
//     cos(πk(j + ½)/N), its eigenvalues −(4/Δz²) sin²(πk/2N), so a step of any length is exp(𝒟ΔtL)
//     applied in that basis: no stability limit, no time error, positivity kept, and the column
//     totals of φ_i and φ_iξ_i kept exactly (the k = 0 mode). (ii) is therefore the exact solution
//     of its semi-discrete equations.
//   - Sources: ∂ξ_i/∂z by central differences of ξ_i = (φ_iξ_i)/φ_i (mirror cells at the walls: zero
//     gradient there), integrated by Heun's method (second order), Strang-split: diffusion Δt/2,
//     sources Δt, diffusion Δt/2 (second order; the second half merged with the next step's first).
//     The sources are stiff while the interface is sharp: at t = 0 the cell just below it has
//     |c_i^φ|/φ_i ≈ 80–100 𝒟/Δz² and dξ_2/dt ≈ 70 (ξ_2 − ξ_1) 𝒟/Δz², because the node jumps at the
//     interface (165 and 252 µm) are much larger than the node spacing there (28 µm). So the step
//     follows them: Δt = θ × the smallest over cells and nodes of φ_i/|c_i^φ| and
//     (ξ_2 − ξ_1)/|dξ_i/dt| at the middle of the previous step, θ = 0.05 (a weight changes by about
//     5 % and a node moves by about 5 % of the node spacing per step at most), growing by at most
//     25 % a step. A step longer than twice that limit at its own middle, or one that leaves a weight
//     non-positive or the nodes out of order, would be shortened and redone (never needed here).
//     760–1780 steps reach τ = 1 (N = 50 … 400); early on they are ~5e-4 Δz²/𝒟, by τ = 1 thousands
//     of times the explicit diffusion limit Δz²/(2𝒟).
//   - Errors: the largest over the cell centres of |ξ_i − ξ_i^exact|/ξ_i^exact; for the weights both
//     the relative |φ_i − φ_i^exact|/φ_i^exact and the absolute |φ_i − φ_i^exact| (equal for both
//     nodes, since φ_1 + φ_2 = M_0 = 0.6 in every cell of every run and of the exact solution). The
//     relative weight error is large where a weight is small: in the tails of the mixing zone a trace
//     of powder B (tenths of a per cent) pulls node 2 of the bottom cells to 150–250 µm with a weight
//     of 0.015–0.05, and the exact rule is steep there.
//
// The grid study (N = 50, 100, 200; 400 as well when plotting): the node and weight errors of (i)
// halve with every doubling of N (ratios 0.42–0.50 from N = 100 to 200), at every time. Their source
// is the initial step: while the interface is narrower than a few cells, the central-difference
// sources lose part of the column's second and third moments (the discrete scheme conserves M_0 and
// M_1 exactly, not M_2 and M_3): three quarters of the loss happen before the diffusion length
// √(𝒟t) reaches one cell, 93 % before it reaches four, and the loss is 0.17 Δz/H of M_2 and
// 0.35 Δz/H of M_3 (−0.085 % and −0.17 % at N = 200). The well-mixed column inherits that deficit:
// 0.23 % on node 1 at N = 200. (ii) loses 23 % of M_2 and 49 % of M_3. Halving θ changes the node
// errors of N = 100 by at most 4 % of themselves.
//
// Checks (the program fails if one does not hold):
//   - the exact rule of the well-mixed column is seed 000 Table 6.4's, 102 µm / 0.360 and
//     314 µm / 0.240, to its printed digits (± 0.5 µm, ± 0.0005);
//   - every run reaches τ = 1 with valid steps and DQMOM solves, and keeps the column totals of
//     φ_1 + φ_2 and φ_1ξ_1 + φ_2ξ_2 (M_0, M_1) to relative 1e-12 (s_0 = s_1 = 0: the sources only
//     move volume and size between the nodes);
//   - (ii) ends where class-wise diffusion must: at τ = 1 (uniform to 3e-5 of the layer contrast)
//     φ_i = (φ_i^A + φ_i^B)/2 = 0.321, 0.279 and ξ_i = (φ_i^A ξ_i^A + φ_i^B ξ_i^B)/(φ_i^A + φ_i^B) =
//     172.7, 202.4 µm, relative 1e-3: the thesis's failure (its weights 0.320, 0.280, nodes 165,
//     190 µm, seed 000 Table 6.6);
//   - (i) converges: at τ = 0.01, 0.05, 0.2 and 1 and for both nodes the error at N = 200 is at most
//     0.6 of the error at N = 100 (first order gives 0.5);
//   - (i) is accurate at N = 200: node errors at most 3 % at τ = 0.01 and 1 % at τ >= 0.05, about
//     twice the measured 1.8 % and 0.40 %;
//   - (ii) is much worse: at those times its largest node error is at least 20 times that of (i) at
//     N = 200 (measured: 42 and more), and at τ = 1 at least 30 % (measured 70 %);
//   - the time step resolves the sources: θ = 0.025 instead of 0.05 changes the node errors at
//     N = 100 by at most 20 % of themselves.
//
// The plot (dqmom_diffusion_column.png): nodes and weights against height at τ = 0.05 for (i) and
// (ii) at N = 200 and for (iii), and the largest node error against τ for every grid.
//
//   dqmom_diffusion_column [output directory for the plot; none: no plot]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "fluidbed/moments/dqmom.hpp"
#include "fluidbed/moments/inversion.hpp"
#include "plot.hpp"

namespace {

namespace fm = fluidbed::moments;
constexpr double pi = std::numbers::pi;
constexpr double micron = 1e-6;

int failures = 0;
void check(bool ok, const char* what) {
  std::printf("  %-100s %s\n", what, ok ? "ok" : "FAILED");
  failures += !ok;
}

// A two-node quadrature: nodes ξ_1 < ξ_2 [m] and their volume fractions.
struct Rule {
  std::array<double, 2> node{}, weight{};
};

// Seed 000 Table 6.2 (ε = 0.400).
constexpr Rule powder_a{{75 * micron, 103 * micron}, {0.262, 0.338}};
constexpr Rule powder_b{{240 * micron, 355 * micron}, {0.380, 0.220}};
constexpr double height = 0.30;        // H [m]: two layers of 15 cm
constexpr double diffusivity = 2.5e-4;  // 𝒟 [m²/s], seed 000 eq. 6.25
constexpr double time_scale = height * height / diffusivity;  // H²/𝒟 = 360 s

// The fraction of powder A at height ζ = z/H and time τ = 𝒟t/H² (τ > 0), from the cosine series
// of the step with zero-flux walls, summed until a term is below 1e-18.
double fraction_a(double zeta, double tau) {
  double a = 0.5;
  for (int n = 1;; n += 2) {
    const double term = 2 / (n * pi) * std::exp(-double(n) * n * pi * pi * tau);
    if (term < 1e-18) break;
    a += ((n / 2) % 2 == 0 ? term : -term) * std::cos(n * pi * zeta);  // sin(nπ/2) = ±1
  }
  return a;
}

double moment(const Rule& r, int k) {
  return r.weight[0] * std::pow(r.node[0], k) + r.weight[1] * std::pow(r.node[1], k);
}

// The two-node Gauss rule of the mixture a A + (1 − a) B (library inversion of M_0 … M_3).
Rule mixture(double a) {
  std::array<double, 4> m{};
  for (int k = 0; k < 4; ++k) m[k] = a * moment(powder_a, k) + (1 - a) * moment(powder_b, k);
  const auto r = fm::invert<2>(m);
  if (r.status != fm::InversionStatus::ok) {
    std::printf("inversion failed at a = %.17g\n", a);
    ++failures;
  }
  return {{r.quadrature.nodes[0], r.quadrature.nodes[1]}, {r.quadrature.weights[0], r.quadrature.weights[1]}};
}

// The two-node DQMOM of the column, fields φ_1, φ_2, φ_1ξ_1, φ_2ξ_2 per cell.
class Column {
 public:
  Column(int cells, bool with_sources, double theta)
      : n_(cells), dz_(height / cells), sources_(with_sources), theta_(theta), u_(4 * std::size_t(cells)),
        cosine_(std::size_t(cells) * cells), eigenvalue_(cells) {
    for (int j = 0; j < n_; ++j) {
      const Rule& r = 2 * j < n_ ? powder_a : powder_b;
      for (int i = 0; i < 2; ++i) {
        field(i)[j] = r.weight[i];
        field(2 + i)[j] = r.weight[i] * r.node[i];
      }
    }
    for (int k = 0; k < n_; ++k) {
      const double s = std::sin(pi * k / (2.0 * n_));
      eigenvalue_[k] = -4 / (dz_ * dz_) * s * s;
      for (int j = 0; j < n_; ++j) cosine_[std::size_t(k) * n_ + j] = std::cos(pi * k * (j + 0.5) / n_);
    }
    if (sources_) limit_ = rates(u_, rate_);
  }

  int cells() const { return n_; }
  long steps() const { return steps_; }
  long rejected() const { return rejected_; }
  long solve_failures() const { return solve_failures_; }
  Rule at(int j) const {
    Rule r;
    for (int i = 0; i < 2; ++i) {
      r.weight[i] = field(i)[j];
      r.node[i] = field(2 + i)[j] / field(i)[j];
    }
    return r;
  }
  // Column total of the moment M_k = Σ φ_i ξ_i^k (times Δz).
  double total(int k) const {
    double sum = 0;
    for (int j = 0; j < n_; ++j) sum += moment(at(j), k);
    return sum * dz_;
  }

  // Integrates to time t_end [s]; false if a step failed. Each step is Strang's splitting
  // diffusion h/2, sources h, diffusion h/2, the second half-step of diffusion merged with the next
  // step's first (one transform per step) and completed at t_end.
  bool advance_to(double t_end) {
    if (!sources_) {  // diffusion alone: exact in one step
      diffuse(t_end - t_);
      t_ = t_end;
      ++steps_;
      return true;
    }
    while (t_ < t_end) {
      double h = std::min({growth * step_, theta_ * limit_, t_end - t_});
      if (t_end - t_ - h < 1e-9 * h) h = t_end - t_;  // no sliver of a step before t_end
      saved_ = u_;
      for (;;) {
        diffuse(pending_ + h / 2);
        const double limit = rates(u_, rate_);
        if (h <= 2 * theta_ * limit) {  // the step is within the limit at its middle as well
          source_step(rate_, h);
          if (valid()) {
            limit_ = limit;
            break;
          }
        }
        u_ = saved_;
        ++rejected_;
        h = std::min(h / 2, theta_ * limit);
        if (h < 1e-12 * t_end) return false;
      }
      pending_ = h / 2;
      t_ = t_end - t_ - h < 1e-9 * h ? t_end : t_ + h;
      step_ = h;
      ++steps_;
    }
    diffuse(pending_);
    pending_ = 0;
    return true;
  }

 private:
  static constexpr double growth = 1.25;

  double* field(int f) { return u_.data() + std::size_t(f) * n_; }
  const double* field(int f) const { return u_.data() + std::size_t(f) * n_; }

  bool valid() const {
    for (int j = 0; j < n_; ++j) {
      const Rule r = at(j);
      if (!(r.weight[0] > 0 && r.weight[1] > 0 && r.node[0] > 0 && r.node[0] < r.node[1])) return false;
    }
    return true;
  }

  // The sources c_i^φ, c_i^ξ of state u into out (same layout); returns the source time scale
  // min(φ_i/|c_i^φ|, (ξ_2 − ξ_1)/|dξ_i/dt|).
  double rates(const std::vector<double>& u, std::vector<double>& out) const {
    const std::size_t n = std::size_t(n_);
    nodes_.resize(2 * n);
    for (std::size_t i = 0; i < 2; ++i)
      for (std::size_t j = 0; j < n; ++j) nodes_[i * n + j] = u[(2 + i) * n + j] / u[i * n + j];
    double limit = 1e300;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t below = j == 0 ? 0 : j - 1, above = j + 1 == n ? j : j + 1;  // mirror cells at the walls
      std::array<double, 2> node{}, intensity{};
      for (std::size_t i = 0; i < 2; ++i) {
        node[i] = nodes_[i * n + j];
        const double gradient = (nodes_[i * n + above] - nodes_[i * n + below]) / (2 * dz_);
        intensity[i] = diffusivity * u[i * n + j] * gradient * gradient;  // C_i = 𝒟 φ_i |∂ξ_i/∂z|²
      }
      const auto s = fm::dqmom::diffusion_sources<double, 2>(node, intensity);
      const auto c = fm::dqmom::solve<double, 2>(node, s);
      if (c.size != 2) ++solve_failures_;
      for (std::size_t i = 0; i < 2; ++i) {
        out[i * n + j] = c.weight[i];
        out[(2 + i) * n + j] = c.weighted_node[i];
        const double weight = u[i * n + j];
        const double node_rate = (c.weighted_node[i] - node[i] * c.weight[i]) / weight;  // dξ_i/dt
        limit = std::min({limit, weight / std::abs(c.weight[i]), (node[1] - node[0]) / std::abs(node_rate)});
      }
    }
    return limit;
  }

  // Heun's method over h for the sources, `rate` the sources of the current state.
  void source_step(const std::vector<double>& rate, double h) {
    stage_ = u_;
    for (std::size_t m = 0; m < u_.size(); ++m) stage_[m] += h * rate[m];
    rates(stage_, stage_rate_);
    for (std::size_t m = 0; m < u_.size(); ++m) u_[m] += h / 2 * (rate[m] + stage_rate_[m]);
  }

  // u ← exp(𝒟 h L) u for the finite-volume Laplacian L with zero-flux walls, in the cosine basis.
  void diffuse(double h) {
    const std::size_t n = std::size_t(n_);
    spectrum_.assign(4 * n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const double* c = cosine_.data() + k * n;
      const double scale = (k == 0 ? 1.0 : 2.0) / n_ * std::exp(diffusivity * eigenvalue_[k] * h);
      for (std::size_t f = 0; f < 4; ++f) {
        const double* v = u_.data() + f * n;
        double sum = 0;
        for (std::size_t j = 0; j < n; ++j) sum += c[j] * v[j];
        spectrum_[f * n + k] = sum * scale;
      }
    }
    std::fill(u_.begin(), u_.end(), 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const double* c = cosine_.data() + k * n;
      for (std::size_t f = 0; f < 4; ++f) {
        const double a = spectrum_[f * n + k];
        double* v = u_.data() + f * n;
        for (std::size_t j = 0; j < n; ++j) v[j] += a * c[j];
      }
    }
  }

  int n_;
  double dz_;
  bool sources_;
  double theta_;
  std::vector<double> u_, cosine_, eigenvalue_;
  std::vector<double> rate_ = std::vector<double>(u_.size()), saved_, stage_,
                      stage_rate_ = std::vector<double>(u_.size()), spectrum_;
  mutable std::vector<double> nodes_;
  double t_ = 0, step_ = 1e300, limit_ = 1e300, pending_ = 0;
  long steps_ = 0, rejected_ = 0;
  mutable long solve_failures_ = 0;
};

// Largest errors over the cell centres against the exact rule.
struct Errors {
  std::array<double, 2> node{}, weight{}, weight_absolute{};  // relative, relative, absolute
  double largest_node() const { return std::max(node[0], node[1]); }
};

Errors errors(const Column& c, double tau) {
  Errors e;
  for (int j = 0; j < c.cells(); ++j) {
    const Rule exact = mixture(fraction_a((j + 0.5) / c.cells(), tau)), r = c.at(j);
    for (int i = 0; i < 2; ++i) {
      e.node[i] = std::max(e.node[i], std::abs(r.node[i] / exact.node[i] - 1));
      e.weight[i] = std::max(e.weight[i], std::abs(r.weight[i] / exact.weight[i] - 1));
      e.weight_absolute[i] = std::max(e.weight_absolute[i], std::abs(r.weight[i] - exact.weight[i]));
    }
  }
  return e;
}

constexpr double compared[] = {0.01, 0.05, 0.2, 1};  // τ of the table and the checks
constexpr double profile_time = 0.05;                 // τ of the profiles in the plot

// Every τ at which errors are recorded: 10 per decade from 1e-3 to 1, and the compared times.
std::vector<double> record_times() {
  std::vector<double> t;
  for (int i = 0; i <= 30; ++i) t.push_back(std::pow(10.0, -3 + i / 10.0));
  t.insert(t.end(), std::begin(compared), std::end(compared));
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end(), [](double x, double y) { return std::abs(x / y - 1) < 1e-9; }), t.end());
  return t;
}

struct Run {
  int cells = 0;
  bool sources = false;
  double theta = 0;
  bool completed = false;
  long steps = 0, rejected = 0, solve_failures = 0;
  std::vector<double> times;
  std::vector<Errors> history;                        // at every recorded τ
  std::vector<Rule> profile;                          // per cell at profile_time
  double conservation = 0;                            // max |total M_0, M_1 / initial − 1|
  std::array<double, 2> early_drift{}, drift{};       // total M_2, M_3 / initial − 1 at τ = 1e-3, 1
  std::vector<Rule> final_state;                      // per cell at τ = 1
  std::vector<std::array<double, 2>> drift_history;   // M_2, M_3 drift at every recorded τ

  // The errors at a recorded τ (only asked of completed runs).
  const Errors& at(double tau) const {
    std::size_t m = 0;
    while (m + 1 < times.size() && std::abs(times[m] / tau - 1) > 1e-9) ++m;
    return history.at(m);
  }
};

Run run(int cells, bool sources, double theta = 0.05) {
  Run out;
  out.cells = cells;
  out.sources = sources;
  out.theta = theta;
  Column column(cells, sources, theta);
  std::array<double, 4> initial{};
  for (int k = 0; k < 4; ++k) initial[k] = column.total(k);
  out.completed = true;
  for (double tau : record_times()) {
    if (!column.advance_to(tau * time_scale)) {
      out.completed = false;
      std::printf("  N = %d, %s: a step failed before tau = %g\n", cells,
                  sources ? "with sources" : "without sources", tau);
      break;
    }
    out.times.push_back(tau);
    out.history.push_back(errors(column, tau));
    for (int k = 0; k < 2; ++k)
      out.conservation = std::max(out.conservation, std::abs(column.total(k) / initial[k] - 1));
    out.drift_history.push_back({column.total(2) / initial[2] - 1, column.total(3) / initial[3] - 1});
    if (std::abs(tau / profile_time - 1) < 1e-9)
      for (int j = 0; j < cells; ++j) out.profile.push_back(column.at(j));
  }
  if (!out.drift_history.empty()) {
    out.early_drift = out.drift_history.front();
    out.drift = out.drift_history.back();
  }
  for (int j = 0; j < cells; ++j) out.final_state.push_back(column.at(j));
  out.steps = column.steps();
  out.rejected = column.rejected();
  out.solve_failures = column.solve_failures();
  out.completed = out.completed && out.solve_failures == 0;
  return out;
}

void print_table(const Run& r) {
  std::printf("  %s, N = %d: %ld steps (%ld redone)\n"
              "  column M_0, M_1 kept to %.0e; M_2, M_3 off by %+.2e, %+.2e at tau = 0.001, %+.2e, %+.2e at tau = 1\n",
              r.sources ? "(i) with sources" : "(ii) without sources", r.cells, r.steps, r.rejected, r.conservation,
              r.early_drift[0], r.early_drift[1], r.drift[0], r.drift[1]);
  for (double tau : compared) {
    const Errors& e = r.at(tau);
    std::printf("    %4.2f  %8.3f %8.3f   %9.3f %9.3f   %7.4f\n", tau, 100 * e.node[0], 100 * e.node[1],
                100 * e.weight[0], 100 * e.weight[1], std::max(e.weight_absolute[0], e.weight_absolute[1]));
  }
}

// The profiles of `with` (sources) and `without` at profile_time, with the exact ones; the largest
// node error against τ of every run in `grids` and of `without`.
void plot_results(const std::string& directory, const Run& with, const Run& without, const std::vector<Run>& grids) {
  const plot::Look exact_look{"#000000", 7, "1"}, with_look = plot::look(0), without_look = plot::look(1);
  char text[200];
  std::snprintf(text, sizeof text, "at 𝒟t/H^{2} = %.2f (t = %.0f s)", profile_time, profile_time * time_scale);
  const std::string when = text;
  plot::Panel nodes("Nodes " + when, "height above the bottom wall z [m]", "quadrature nodes ξ_1 < ξ_2 (diameters) [µm]");
  plot::Panel weights("Weights " + when, "height above the bottom wall z [m]",
                      "weight φ_i of node ξ_i (volume fraction) [–]");
  for (plot::Panel* p : {&nodes, &weights}) {
    p->xrange = plot::range(0, height);
    p->commands.push_back("set arrow from 0.15, graph 0 to 0.15, graph 1 nohead dt 3 lw 1.5 lc rgb '#808080'");
    p->commands.push_back("set label 'initially A' at 0.075, graph 0.04 center tc rgb '#606060'");
    p->commands.push_back("set label 'initially B' at 0.225, graph 0.04 center tc rgb '#606060'");
  }
  nodes.yrange = "[0:460]";
  nodes.key = "top left box opaque";
  weights.yrange = "[0:0.8]";
  weights.key = "top right box opaque";
  for (int i = 0; i < 2; ++i)
    for (plot::Panel* p : {&nodes, &weights}) {
      const bool is_node = p == &nodes;
      const auto value = [&](const Rule& r) { return is_node ? r.node[i] / micron : r.weight[i]; };
      const auto cells = [&](const Run& r, const std::string& legend, const plot::Look& l, int first) {
        plot::Series& s = p->add(i == 0 ? legend : "", l, r.cells / 25, first);
        for (int j = 0; j < r.cells; ++j) s.point((j + 0.5) * height / r.cells, value(r.profile[std::size_t(j)]));
      };
      std::snprintf(text, sizeof text, "(ii) without sources, N = %d cells", without.cells);
      cells(without, text, without_look, 0);
      std::snprintf(text, sizeof text, "(i) with sources, N = %d cells", with.cells);
      cells(with, text, with_look, with.cells / 50);
      plot::Series& exact = p->add(i == 0 ? "(iii) exact moments, inverted" : "", exact_look.line(1.5));
      for (int m = 0; m <= 300; ++m)
        exact.point(m * height / 300, value(mixture(fraction_a(m / 300.0, profile_time))));
    }
  nodes.commands.push_back("set label 'ξ_2' at 0.005, 280 font ',14'");
  nodes.commands.push_back("set label 'ξ_1' at 0.005, 60 font ',14'");
  weights.commands.push_back("set label 'φ_1' at 0.005, 0.60 font ',14'");
  weights.commands.push_back("set label 'φ_2' at 0.005, 0.11 font ',14'");

  plot::Panel error("Largest node error over the column",
                    "dimensionless time 𝒟t/H^{2} [–]\n(H = 0.30 m, 𝒟 = 2.5·10^{-4} m^{2}/s: t = 360 s × 𝒟t/H^{2})",
                    "max over z and i of |ξ_i − ξ_i^{exact}| / ξ_i^{exact} [%]");
  error.log_x = error.log_y = true;
  error.xrange = "[1e-3:1]";
  error.yrange = "[0.01:500]";
  error.key = "bottom left box opaque";
  std::snprintf(text, sizeof text, "(ii) without sources, N = %d", without.cells);
  plot::Series& s = error.add(text, without_look, 3, 1);
  for (std::size_t m = 0; m < without.times.size(); ++m)
    s.point(without.times[m], 100 * without.history[m].largest_node());
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const Run& r = grids[g];
    std::snprintf(text, sizeof text, "(i) with sources, N = %d", r.cells);
    // the grid of the profiles in their look, the others in looks of their own
    const plot::Look l = r.cells == with.cells ? with_look : plot::look(r.cells < with.cells ? 2 + int(g) : 7);
    plot::Series& e = error.add(text, l, 3, int(g) % 3);
    for (std::size_t m = 0; m < r.times.size(); ++m) e.point(r.times[m], 100 * r.history[m].largest_node());
  }

  const std::string png = plot::render(
      directory, "dqmom_diffusion_column", {nodes, weights, error},
      {"Powder A (nodes 75, 103 µm) below powder B (240, 355 µm), mixing by diffusion in a closed column: "
       "two-node DQMOM with (i) and without (ii) the diffusion sources, against the exact solution (iii)",
       3, 640, 520});
  if (!png.empty()) std::printf("plotted %s\n", png.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<std::string> directory = plot::output_directory(argc, argv);
  std::printf("Powder A below (75 um, phi 0.262; 103 um, phi 0.338), powder B above (240 um, 0.380; 355 um, 0.220),\n"
              "column H = %.2f m, zero-flux walls, D = %.2e m^2/s: tau = D t/H^2, t = %.0f s * tau\n\n",
              height, diffusivity, time_scale);

  std::printf("Exact rule of the well-mixed column (seed 000 Table 6.4: 102 um 0.360, 314 um 0.240):\n");
  const Rule mixed = mixture(0.5);
  std::printf("  %.3f um %.5f, %.3f um %.5f\n", mixed.node[0] / micron, mixed.weight[0], mixed.node[1] / micron,
              mixed.weight[1]);
  check(std::abs(mixed.node[0] / micron - 102) <= 0.5 && std::abs(mixed.node[1] / micron - 314) <= 0.5 &&
            std::abs(mixed.weight[0] - 0.360) <= 0.0005 && std::abs(mixed.weight[1] - 0.240) <= 0.0005,
        "Table 6.4 to its printed digits");

  std::vector<int> grids{50, 100, 200};
  if (directory) grids.push_back(400);
  std::printf("\nLargest errors over the column against (iii): relative of the nodes and of the weights [%%], and\n"
              "absolute of the weights (phi_1 + phi_2 = M_0 = 0.6 in every cell, so |dphi_1| = |dphi_2|):\n"
              "    tau    xi_1 [%%]  xi_2 [%%]  phi_1 [%%]  phi_2 [%%]   |dphi_i|\n");
  std::vector<Run> with;
  for (int cells : grids) {
    with.push_back(run(cells, true));
    print_table(with.back());
  }
  const Run& r100 = with[1];
  const Run& r200 = with[2];
  const Run without = run(200, false);
  print_table(without);
  const Run half_step = run(100, true, 0.025);
  std::printf("  time step: theta = 0.025 instead of 0.05 at N = 100 changes the node errors by\n   ");
  double time_effect = 0;
  for (double tau : compared)
    for (int i = 0; i < 2; ++i) {
      const double change = half_step.at(tau).node[i] / r100.at(tau).node[i] - 1;
      time_effect = std::max(time_effect, std::abs(change));
      std::printf(" %+.1f %%", 100 * change);
    }
  std::printf(" of themselves\n");

  std::printf("\nChecks:\n");
  bool completed = without.completed && half_step.completed;
  double conservation = std::max(without.conservation, half_step.conservation);
  for (const Run& r : with) {
    completed = completed && r.completed;
    conservation = std::max(conservation, r.conservation);
  }
  check(completed, "every run reached tau = 1 (no step failed, every DQMOM system solved)");
  if (!completed) {
    std::printf("%d checks FAILED\n", failures);
    return 1;
  }
  check(conservation <= 1e-12, "column totals of M_0 and M_1 kept to relative 1e-12 in every run");
  {
    Rule expected;
    for (int i = 0; i < 2; ++i) {
      expected.weight[i] = (powder_a.weight[i] + powder_b.weight[i]) / 2;
      expected.node[i] = (powder_a.weight[i] * powder_a.node[i] + powder_b.weight[i] * powder_b.node[i]) /
                         (powder_a.weight[i] + powder_b.weight[i]);
    }
    double worst = 0;
    for (const Rule& r : without.final_state)
      for (int i = 0; i < 2; ++i)
        worst = std::max({worst, std::abs(r.node[i] / expected.node[i] - 1),
                          std::abs(r.weight[i] / expected.weight[i] - 1)});
    std::printf("  (ii) at tau = 1: class-wise mixing gives %.1f um (%.3f), %.1f um (%.3f); largest deviation %.1e\n",
                expected.node[0] / micron, expected.weight[0], expected.node[1] / micron, expected.weight[1], worst);
    check(worst <= 1e-3, "(ii) ends at the class-wise mixture (thesis Table 6.6's failure), relative 1e-3");
  }
  {
    double worst_ratio = 0;
    for (double tau : compared)
      for (int i = 0; i < 2; ++i) worst_ratio = std::max(worst_ratio, r200.at(tau).node[i] / r100.at(tau).node[i]);
    char what[160];
    std::snprintf(what, sizeof what, "(i) converges: node error(N = 200) / error(N = 100) at most 0.6 (largest %.2f)",
                  worst_ratio);
    check(worst_ratio <= 0.6, what);
  }
  {
    bool ok = true;
    for (double tau : compared) ok = ok && r200.at(tau).largest_node() <= (tau < 0.02 ? 0.03 : 0.01);
    check(ok, "(i) at N = 200: node errors at most 3 % at tau = 0.01, 1 % at tau >= 0.05");
  }
  {
    double smallest_ratio = 1e300;
    for (double tau : compared)
      smallest_ratio = std::min(smallest_ratio, without.at(tau).largest_node() / r200.at(tau).largest_node());
    char what[160];
    std::snprintf(what, sizeof what,
                  "(ii) node errors at least 20 times those of (i) at every compared time (smallest ratio %.0f)",
                  smallest_ratio);
    check(smallest_ratio >= 20, what);
    check(without.at(1).largest_node() >= 0.30, "(ii) node error at tau = 1 at least 30 %");
  }
  check(time_effect <= 0.2, "time step: halving theta changes the node errors by at most 20 % of themselves");

  if (directory) plot_results(*directory, r200, without, with);
  else std::printf("(no output directory given: no plot)\n");
  if (failures) std::printf("%d checks FAILED\n", failures);
  return failures == 0 ? 0 : 1;
}
