// fluidbed — correction of corrupted moment sets (seed 003, section "The numerical corruption of
// higher-order advected moments").
//
// Finite-volume advection of each moment as an independent scalar does not preserve the
// relations among them (Wright (2007), "Numerical advection of moments of the particle size
// distribution in Eulerian models", J. Aerosol Sci. 38, 352–369, seed 003 ref. 47): sets leave
// moment space and the inversion gives negative or complex nodes. Seed 003 restores them in
// the order implemented here:
//   1. McGraw's correction — McGraw, R. (2006), "Correcting moment sequences for errors
//      associated with advective transport", Brookhaven National Laboratory report,
//      http://www.ecd.bnl.gov/pubs/momentcorrection_mcgraw2006.pdf (seed 003 ref. 59; the
//      report itself could not be retrieved: what follows is the seed's description — change
//      the one moment that most reduces the third differences of ln M_k, i.e. moves the set
//      toward the nearest log-normal — made explicit as a least-squares projection): with
//      ℓ_k = ln m_k and the third differences d_j = ℓ_{j+3} − 3ℓ_{j+2} + 3ℓ_{j+1} − ℓ_j
//      (j = 0 … L − 4; d = 0 for a log-normal, whose ℓ_k is a parabola), multiplying one
//      moment m_k by c changes d by (ln c) b^(k), b^(k)_j = ∂d_j/∂ℓ_k ∈ {−1, 3, −3, 1}. The
//      least-squares factor is ln c_k = −(b^(k)·d)/|b^(k)|², leaving |d|²(1 − cos²θ_k) with
//      cos²θ_k = (b^(k)·d)²/(|b^(k)|²|d|²); the moment k* = argmax_k cos²θ_k is changed, one per
//      iteration ("the moment that after adjustment maximizes the smoothness of ln M_k");
//      stop as soon as ln m_k is convex (every Δ²_k = ℓ_k − 2ℓ_{k+1} + ℓ_{k+2} >= 0, McGraw's
//      criterion) or after max_iterations;
//   2. the full realizability test (realizability.hpp: every ζ_j > 0 — seed 003 checks the
//      Hankel determinants of order >= 4, which the ζ signs decide, since
//      ζ_k = H_k H_{k−3}/(H_{k−1} H_{k−2}): every ζ_k > 0 iff every H_k > 0);
//   3. if it fails, the log-normal sharing M_0, M_1, M_2 (M_k = M_0 r^k q^{k(k−1)/2},
//      r = M_1/M_0, q = M_0 M_2/M_1²) with the set as McGraw left it. Seed 003 says "with the
//      original set"; the two agree unless McGraw changed M_1 or M_2, i.e. found one of them to
//      be the corrupted moment, and then its value is the better one: in the 4-class mixture of
//      seed 000 Table 6.4 (75, 103, 240, 355 µm; volume fractions 0.131, 0.169, 0.190, 0.110)
//      with M_1 × 1.3, M_1 is brought back from 145.4 to 115.0 (exact 111.88), and the corrupted
//      145.4 would give M_0 M_2 < M_1², no log-normal at all. protected_moments = 3 gives the
//      literal reading.
//
// Decisions (the seed leaves them open):
//   * Candidate set k = protected_moments … L − 1, default protected_moments = 1: M_0 (the
//     solids volume fraction) is never changed, as in the published implementations. M_1 and M_2
//     stay candidates: when the corrupted moment is M_1 McGraw picks it (the mixture above with
//     M_1 × 1.3: k* = 1, 115.0 against the exact 111.88), and forbidding it would move the error into the
//     higher moments. Set protected_moments = 3 to keep d43 and the variance. The fallback
//     changes nothing below M_3 (below M_2 in the monodisperse case) beyond what McGraw did.
//   * Exact ties of cos²θ go to the higher index (corruption "usually affects higher-order
//     moments", seed 003).
//   * McGraw runs only for L >= 6 moments, as seed 003 says ("when tracking sets of six or more
//     moments"; with L = 4 there is one third difference and every candidate cancels it), and
//     only if every moment is > 0 (logarithms); otherwise the fallback acts directly.
//   * Stopping: convexity, then the full test. Iterating until the full test passes instead
//     drifts M_1, M_2 (35–46 iterations and M_1 moved by ~6% on the mixture above with one of
//     M_1 … M_7 corrupted; no convergence in 100 iterations on seed 003 Table 1 powder A): the
//     fallback is cheaper and keeps M_0 … M_2.
//   * max_iterations = 20 (published codes use 20–100; each iteration only lowers |d|, and the
//     convexity stop takes 1 iteration on every corrupted mixture of tests/test_moment_correction.cpp).
//   * A set on the boundary of moment space within round-off — some ζ_j, j >= 2, up to the first
//     failing one, with |ζ_j| <= degenerate_tolerance ζ_1 — is a valid degenerate set (fewer
//     atoms than nodes; adaptive.hpp inverts it) and is left unchanged; correcting it would
//     replace, e.g., two exact atoms by a log-normal. Default degenerate_tolerance = ε^{1/3}
//     (6.06e-6 in double): measured on 19 500 sets of 1 to 4 exact atoms (>= 1% apart) rounded
//     to double and given more moments than atoms, |ζ_j|/ζ_1 at the degenerate level has median
//     6e-14, 99th percentile 4e-8, maximum 3e-4. Larger than the adaptive τ = ε^{2/3} because
//     "unchanged" is the safe outcome here, while there the rule discards moments; a real PSD
//     has ζ_j/ζ_1 ~ c.v.², above ε^{1/3} for c.v. > 0.25%.
//   * M_0 M_2 < M_1² (q < 1): M_0 … M_2 are themselves not realizable and no log-normal
//     exists; the set becomes the monodisperse M_k = M_0 r^k, r = M_1/M_0 (all the solids at
//     the mean size d43, M_0 and M_1 kept). M_1 <= 0 (no size scale), m_0 <= 0, NaN or ±∞:
//     nothing can be corrected (status failed, moments returned as given).
//   * A correction is reported only if every moment it returns is finite and > 0. McGraw's
//     factor c = exp(ln c) over- or underflows where a moment was corrupted by more than the
//     range (M_2 = 8e-323 in a set in SI units): mcgraw_correct then fails, and correct_moments
//     goes on to the fallback from the set as given. The fallback's M_0 r^k q^{k(k−1)/2}
//     overflows for a broad set at high k, underflows for small sizes in float, and is NaN where
//     r or q are not normal numbers (a set spanning the whole range): status failed then too,
//     the moments as given — no other correction is attempted, since none shares M_0 … M_2. So
//     is a fill whose moments are finite and positive but span more than the range once
//     exactly scaled (realizability(): invalid_input; a broad log-normal in float), which no
//     inversion could use.
// Only sizes ([0, ∞)) are corrected: the logarithms and the fallback need positive moments.
#pragma once

#include <array>
#include <cmath>
#include <span>

#include "../core/config.hpp"
#include "adaptive.hpp"
#include "moment_set.hpp"
#include "realizability.hpp"
#include "recurrence.hpp"

namespace fluidbed::moments {

enum class CorrectionStatus {
  unchanged,     // realizable as given, or on the boundary within round-off: nothing changed
  mcgraw,        // made realizable by McGraw's iterations
  lognormal,     // replaced above M_2 by the log-normal sharing M_0, M_1, M_2
  monodisperse,  // M_0 M_2 < M_1²: replaced by M_0 r^k (M_0, M_1 kept)
  zero_mass,     // every moment 0 (an empty cell): nothing to correct
  failed,        // NaN/±∞, m_0 <= 0 or m_1 <= 0, or no correction with finite positive moments
                 // (beyond the range of T): not correctable, moments returned as given; or a
                 // count outside 1 … 2N: nothing read, size 0
};

template <class T>
struct CorrectionOptions {
  int protected_moments = 1;  // McGraw never changes M_0 … M_{protected_moments − 1} (>= 1)
  int max_iterations = 20;
  T degenerate_tolerance = default_degeneracy_threshold<T>();
};

template <class T, int N>
struct CorrectionResult {
  std::array<T, 2 * N> moments{};  // the corrected set, size entries
  int size = 0;
  std::array<T, 2 * N> ratio{};      // corrected/original, 1 where unchanged (±∞ for an original 0)
  std::array<bool, 2 * N> changed{};
  int iterations = 0;                // McGraw iterations performed
  CorrectionStatus status = CorrectionStatus::failed;
  int realizable_moments = 0;        // of the returned set, on [0, ∞) (realizability())
};

namespace detail {

// Whether ln m̃_k (l[0 … L−1]) is convex: every second difference >= 0.
template <class T>
FLUIDBED_HOST_DEVICE bool log_convex(const T* l, int L) {
  for (int k = 0; k + 2 < L; ++k)
    if (!(l[k] - T(2) * l[k + 1] + l[k + 2] >= T(0))) return false;
  return true;
}

// One McGraw iteration on l = ln m̃: changes l[k*] and returns k* (−1 if no change is possible:
// d = 0, i.e. a log-normal parabola, concave or not). ln_c receives ln c_{k*}.
template <class T, int N>
FLUIDBED_HOST_DEVICE int mcgraw_step(T* l, int L, int first_candidate, T& ln_c) {
  FLUIDBED_EXPECTS(L <= 2 * N);
  T d[2 * N]{};
  T dd(0);
  for (int j = 0; j + 3 < L; ++j) {
    d[j] = l[j + 3] - T(3) * l[j + 2] + T(3) * l[j + 1] - l[j];
    dd += d[j] * d[j];
  }
  if (!(dd > T(0))) return -1;
  constexpr int coefficient[4] = {-1, 3, -3, 1};  // ∂d_j/∂l_{j+offset}
  int best = -1;
  T best_cos2(-1);
  for (int k = first_candidate; k < L; ++k) {
    T bb(0), bd(0);
    for (int j = k - 3; j <= k; ++j)
      if (j >= 0 && j + 3 < L) {
        const T b = T(coefficient[k - j]);
        bb += b * b;
        bd += b * d[j];
      }
    if (!(bb > T(0))) continue;
    const T cos2 = bd * bd / (bb * dd);
    if (cos2 >= best_cos2) {
      best_cos2 = cos2;
      best = k;
      ln_c = -bd / bb;
    }
  }
  if (best >= 0) l[best] += ln_c;
  return best;
}

// A set whose ζ (up to the first failing one) come within tolerance × ζ_1 of 0: on the boundary.
template <class T, int N>
FLUIDBED_HOST_DEVICE bool on_boundary(const RealizabilityReport<T, N>& report, const T& tolerance) {
  using std::abs;
  const int last = report.first_failing_index > 0 ? report.first_failing_index : report.zeta_count;
  if (!(report.zeta_count >= 1 && report.zeta[0] > T(0))) return false;
  for (int j = 2; j <= last; ++j)
    if (abs(report.zeta[j - 1]) <= tolerance * report.zeta[0]) return true;
  return false;
}

// Starts a result: copies m, ratio 1, checks the input. Returns false (status set) when the
// set cannot be corrected at all or is empty; a count outside 1 … 2N is not copied (size 0).
template <class T, int N>
FLUIDBED_HOST_DEVICE bool start_correction(std::span<const T> m, CorrectionResult<T, N>& out) {
  if (!count_within(m.size(), 1, 2 * N)) {
    out.size = 0;
    out.status = CorrectionStatus::failed;
    return false;
  }
  out.size = int(m.size());
  for (int k = 0; k < out.size; ++k) {
    out.moments[k] = m[k];
    out.ratio[k] = T(1);
  }
  // The input checks of the inversion (non-finite, empty, m_0 <= 0), plus m_1 > 0: the
  // logarithms below need positive moments.
  switch (input_status(m)) {
    case InversionStatus::zero_mass:
      out.status = CorrectionStatus::zero_mass;
      break;
    case InversionStatus::ok:
      out.status = out.size < 2 || m[1] > T(0) ? CorrectionStatus::unchanged : CorrectionStatus::failed;
      break;
    default:
      out.status = CorrectionStatus::failed;
  }
  return out.status == CorrectionStatus::unchanged;
}

// Gives up a correction whose moments T cannot represent: the moments as given, status failed
// (realizable_moments left to the caller).
template <class T, int N>
FLUIDBED_HOST_DEVICE void give_up(std::span<const T> m, CorrectionResult<T, N>& out) {
  out = CorrectionResult<T, N>{};
  start_correction(m, out);
  out.status = CorrectionStatus::failed;
}

// McGraw's iterations on out.moments (all > 0, size >= 6) until ln m_k is convex. Returns false,
// out.moments part-way, if a step would make a moment ±∞ or 0: ln c is computed on the scaled
// logarithms and is fine, but c = exp(ln c) applied to the moment in the caller's units is not.
template <class T, int N>
FLUIDBED_HOST_DEVICE bool run_mcgraw(CorrectionResult<T, N>& out, int protected_moments, int max_iterations) {
  using std::exp;
  using std::isfinite;
  using std::log;
  const int L = out.size;
  const ScaledMoments<T, N> scaled = scaled_moments<T, N>(std::span<const T>(out.moments.data(), std::size_t(L)));
  T l[2 * N]{};
  for (int k = 0; k < L; ++k) l[k] = log(scaled.values[std::size_t(k)]);
  const int first = protected_moments < 1 ? 1 : protected_moments;
  while (out.iterations < max_iterations && !log_convex(l, L)) {
    T ln_c(0);
    const int k = mcgraw_step<T, N>(l, L, first, ln_c);
    if (k < 0) break;
    const T factor = exp(ln_c);
    const T moment = out.moments[k] * factor;
    if (!(isfinite(moment) && moment > T(0))) return false;
    out.moments[k] = moment;
    out.ratio[k] *= factor;
    out.changed[k] = true;
    ++out.iterations;
  }
  return true;
}

}  // namespace detail

// McGraw's iterations alone (step 1 above), until ln m_k is convex or max_iterations: status
// mcgraw if it changed something, unchanged if the set was convex (or L < 6, or a moment <= 0),
// zero_mass or failed for such inputs, failed (moments as given) if a step leaves the range of
// T. Realizability is reported, not enforced. A count outside 1 … 2N: failed, size 0.
template <class T, int N>
FLUIDBED_HOST_DEVICE CorrectionResult<T, N> mcgraw_correct(std::span<const T> m, const CorrectionOptions<T>& options = {}) {
  CorrectionResult<T, N> out;
  if (!detail::start_correction(m, out)) return out;
  bool positive = true;
  for (int k = 0; k < out.size; ++k) positive = positive && m[k] > T(0);
  if (positive && out.size >= 6 && !detail::run_mcgraw(out, options.protected_moments, options.max_iterations))
    detail::give_up(m, out);
  else if (out.iterations > 0)
    out.status = CorrectionStatus::mcgraw;
  out.realizable_moments =
      realizability<T, N>(std::span<const T>(out.moments.data(), m.size())).realizable_moments;
  return out;
}

// The full correction of seed 003 (steps 1–3 above, with the decisions listed there; a McGraw
// step beyond the range of T hands the set as given to the fallback, a fallback beyond it gives
// status failed with the moments as given). A count outside 1 … 2N: failed, size 0.
template <class T, int N>
FLUIDBED_HOST_DEVICE CorrectionResult<T, N> correct_moments(std::span<const T> m,
                                                            const CorrectionOptions<T>& options = {}) {
  using std::exp;
  using std::isfinite;
  using std::log;
  CorrectionResult<T, N> out;
  if (!detail::start_correction(m, out)) return out;
  const RealizabilityReport<T, N> given = realizability<T, N>(m);
  out.realizable_moments = given.realizable_moments;
  if (given.status == InversionStatus::ok || detail::on_boundary(given, options.degenerate_tolerance)) return out;

  out = mcgraw_correct<T, N>(m, options);  // failed here only for a step beyond the range: m as given
  if (out.iterations > 0) {
    const RealizabilityReport<T, N> after = realizability<T, N>(std::span<const T>(out.moments.data(), m.size()));
    if (after.status == InversionStatus::ok || detail::on_boundary(after, options.degenerate_tolerance)) return out;
  }

  // Fallback from M_0, M_1, M_2 as McGraw left them (size >= 2 here: one moment is realizable).
  const int L = out.size;
  const T low[3] = {out.moments[0], out.moments[1], L >= 3 ? out.moments[2] : T(0)};
  const bool lognormal = L >= 3 && low[0] * low[2] > low[1] * low[1];
  const LognormalParameters<T> p =
      lognormal ? lognormal_matching(low[0], low[1], low[2]) : LognormalParameters<T>{log(low[1] / low[0]), T(0)};
  lognormal_moments(low[0], p, std::span<T>(out.moments.data(), std::size_t(L)));
  const int kept = lognormal ? 3 : 2;
  bool representable = true;
  for (int k = 0; k < L; ++k) {
    if (k < kept) out.moments[k] = low[k];  // exactly, not through exp(ln ·)
    representable = representable && isfinite(out.moments[k]) && out.moments[k] > T(0);
    out.changed[k] = out.changed[k] || k >= kept;
    out.ratio[k] = out.moments[k] / m[k];
  }
  // Finite positive moments can still span more than the range once scaled (a broad log-normal
  // in float): the inversion could not use them, realizability() says invalid_input. (Moments
  // that are not finite and positive are not analysed: the default report says invalid_input.)
  const RealizabilityReport<T, N> filled = representable
                                               ? realizability<T, N>(std::span<const T>(out.moments.data(), m.size()))
                                               : RealizabilityReport<T, N>{};
  if (filled.status == InversionStatus::invalid_input) {
    detail::give_up(m, out);
    out.realizable_moments = given.realizable_moments;
    return out;
  }
  out.status = lognormal ? CorrectionStatus::lognormal : CorrectionStatus::monodisperse;
  out.realizable_moments = filled.realizable_moments;
  return out;
}

}  // namespace fluidbed::moments
