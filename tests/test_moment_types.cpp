// Every public function of the moments headers in float, double and long double
// (TEST_CASE_TEMPLATE), against references exact in each type or exact rationals rounded once:
// sets of atoms at powers of two with dyadic weights, whose moments every type represents
// exactly and whose recurrence, Stieltjes coefficients and Hankel determinants are small
// rationals (computed with Python's fractions.Fraction); Gauss–Legendre and Gauss–Radau rules
// in closed form; sieve bins with power-of-two edges (exact bin integrals). So a result differs
// from its reference only by the rounding inside the function, and each tolerance is a multiple
// of the type's epsilon, the same multiple for the three types: 64 ε for a few operations,
// more where the measured conditioning of the map from moments to rule says so (named where used).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "fluidbed/moments.hpp"
#include "same_arithmetic.hpp"

using namespace fluidbed::moments;

namespace {

// |got − expected| <= factor ε_T scale (scale = |expected| by default: relative).
template <class T>
bool close(const T& got, const T& expected, double factor, const T& scale) {
  using std::abs;
  return abs(got - expected) <= T(factor) * std::numeric_limits<T>::epsilon() * scale;
}
template <class T>
bool close(const T& got, const T& expected, double factor = 64) {
  using std::abs;
  return close(got, expected, factor, abs(expected));
}

// p/q rounded once to T.
template <class T>
T ratio(long long p, long long q) {
  return T(p) / T(q);
}

// Three atoms at 1, 2, 4 (times the length unit 2^length) with weights 1/4, 1/2, 1/4: moments
// m_0 … m_5 = 1, 9/4, 25/4, 81/4, 289/4, 1089/4 (times 2^(k length)), exact in every type;
// α = 9/4, 225/76, 34/19; β_1, β_2 = 19/16, 288/361; ζ = 9/4, 19/36, 416/171, 81/247, 19/13;
// H_0 … H_5 = 1, 9/4, 19/16, 13/2, 9/8, 9 (lengths to the powers of recurrence.hpp).
template <class T>
std::array<T, 6> three_atoms(int length = 0) {
  const std::array<T, 6> unit{T(1), ratio<T>(9, 4), ratio<T>(25, 4), ratio<T>(81, 4), ratio<T>(289, 4),
                              ratio<T>(1089, 4)};
  std::array<T, 6> m{};
  for (int k = 0; k < 6; ++k) m[std::size_t(k)] = std::ldexp(unit[std::size_t(k)], k * length);
  return m;
}
template <class T>
const std::array<T, 3> atom_nodes{T(1), T(2), T(4)};
template <class T>
const std::array<T, 3> atom_weights{T(0.25), T(0.5), T(0.25)};

// Four atoms at 1, 2, 4, 8 with weights 1/8, 3/8, 3/8, 1/8 (m_7 = 268336.125: 21 bits).
template <class T>
std::array<T, 8> four_atoms() {
  const T x[4] = {1, 2, 4, 8}, w[4] = {0.125, 0.375, 0.375, 0.125};
  std::array<T, 8> m{};
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 4; ++i) m[std::size_t(k)] += w[i] * std::pow(x[i], T(k));
  return m;
}

// The rule recovers the three atoms in the length unit 2^length.
template <class T, int N>
void check_three_atoms(const Quadrature<T, N>& q, double factor, int length = 0) {
  REQUIRE(q.size == 3);
  for (int i = 0; i < 3; ++i) {
    CHECK(close(q.nodes[std::size_t(i)], T(std::ldexp(atom_nodes<T>[std::size_t(i)], length)), factor));
    CHECK(close(q.weights[std::size_t(i)], atom_weights<T>[std::size_t(i)], factor, T(1)));
  }
}

// The exact recurrence of the three atoms (unit length).
template <class T>
Recurrence<T, 3> three_atom_recurrence() {
  Recurrence<T, 3> r;
  r.alpha = {ratio<T>(9, 4), ratio<T>(225, 76), ratio<T>(34, 19)};
  r.beta = {T(1), ratio<T>(19, 16), ratio<T>(288, 361)};
  r.size = 3;
  return r;
}

// Conditioning of the three-atom inversion, measured over every option and unit below: nodes
// and weights from the moments within 46 ε (float), 24 ε (double), 16 ε (long double), as much
// with invert_eigen; 256 ε leaves a factor 5.
constexpr double inversion_factor = 256;

}  // namespace

TEST_CASE_TEMPLATE("types: recurrence.hpp — scaling, Wheeler, product-difference, ζ", T, float, double, long double) {
  for (const int length : {0, -13, 9}) {
    INFO("length unit 2^" << length);
    const std::array<T, 6> m = three_atoms<T>(length);
    const std::span<const T> set(m);
    // The scaling is exact: m_k = 2^(a + k b) m̃_k, and m̃_0 within a factor √2 of 1.
    const MomentScaling s = scaling_of(set);
    std::array<T, 6> scaled{};
    REQUIRE(scale_moments(set, s, std::span<T>(scaled)));
    for (int k = 0; k < 6; ++k)
      CHECK(std::ldexp(scaled[std::size_t(k)], s.weight_exponent + k * s.length_exponent) == m[std::size_t(k)]);
    CHECK(scaled[0] >= T(0.7));
    CHECK(scaled[0] <= T(1.42));
    const Recurrence<T, 3> exact = three_atom_recurrence<T>();
    for (const RecurrenceAlgorithm algorithm : {RecurrenceAlgorithm::wheeler, RecurrenceAlgorithm::product_difference}) {
      const Recurrence<T, 3> r = recurrence<T, 3>(set, algorithm);
      REQUIRE(r.size == 3);
      for (int k = 0; k < 3; ++k) {
        CHECK(close(r.alpha[std::size_t(k)], T(std::ldexp(exact.alpha[std::size_t(k)], length))));
        if (k > 0) CHECK(close(r.beta[std::size_t(k)], T(std::ldexp(exact.beta[std::size_t(k)], 2 * length))));
      }
      CHECK(r.beta[0] == T(1));
    }
    // The unscaled algorithms on the scaled moments, then unscale(): the same recurrence.
    Recurrence<T, 3> w = wheeler_unscaled<T, 3>(std::span<const T>(scaled));
    unscale(w, s);
    const Recurrence<T, 3> direct = recurrence<T, 3>(set);
    for (int k = 0; k < 3; ++k) {
      CHECK(w.alpha[std::size_t(k)] == direct.alpha[std::size_t(k)]);
      CHECK(w.beta[std::size_t(k)] == direct.beta[std::size_t(k)]);
    }
    std::array<T, 6> zeta_pd{};
    const Recurrence<T, 3> pd = product_difference_unscaled<T, 3>(std::span<const T>(scaled), &zeta_pd);
    CHECK(pd.size == 3);
    const long long zeta[5][2] = {{9, 4}, {19, 36}, {416, 171}, {81, 247}, {19, 13}};
    const std::array<T, 6> from_wheeler = stieltjes_coefficients(direct);
    for (int j = 0; j < 5; ++j) {
      const T expected = std::ldexp(ratio<T>(zeta[j][0], zeta[j][1]), length);
      CHECK(close(from_wheeler[std::size_t(j)], expected));
      CHECK(close(T(std::ldexp(zeta_pd[std::size_t(j)], s.length_exponent)), expected));
    }
  }
}

TEST_CASE_TEMPLATE("types: jacobi_eigen.hpp and eigen_backend.hpp — every solver on exact recurrences", T, float,
                   double, long double) {
  using std::sqrt;
  // Gauss–Legendre on 0 to 1: α = 1/2, β_1 = 1/12 → nodes 1/2 ∓ √3/6, weights 1/2.
  Recurrence<T, 2> legendre;
  legendre.alpha = {T(0.5), T(0.5)};
  legendre.beta = {T(1), ratio<T>(1, 12)};
  legendre.size = 2;
  const Quadrature<T, 2> two = gauss_closed_form(legendre);
  REQUIRE(two.size == 2);
  CHECK(close(two.nodes[0], T(0.5) - sqrt(T(3)) / T(6)));
  CHECK(close(two.nodes[1], T(0.5) + sqrt(T(3)) / T(6)));
  CHECK(close(two.weights[0], T(0.5)));
  CHECK(close(two.weights[1], T(0.5)));
  legendre.size = 1;
  const Quadrature<T, 2> one = gauss_closed_form(legendre);
  CHECK((one.size == 1 && one.nodes[0] == T(0.5) && one.weights[0] == T(1)));

  const Recurrence<T, 3> r = three_atom_recurrence<T>();
  Quadrature<T, 3> q;
  REQUIRE(gauss_golub_welsch(r, q));
  check_three_atoms(q, 64);
  check_three_atoms(gauss_three_nodes(r), 64);
  REQUIRE(gauss_eigen_tridiagonal(r, q));
  check_three_atoms(q, 64);
  // The lane form of the three-node solver, on one cell (V = T).
  const T alpha[3] = {r.alpha[0], r.alpha[1], r.alpha[2]}, beta[3] = {r.beta[0], r.beta[1], r.beta[2]};
  T nodes[3], weights[3];
  CHECK(gauss_three_nodes(alpha, beta, nodes, weights) > T(0));  // within the spread limit
  for (int i = 0; i < 3; ++i) {
    CHECK(close(nodes[i], atom_nodes<T>[std::size_t(i)]));
    CHECK(close(weights[i], atom_weights<T>[std::size_t(i)], 64, T(1)));
  }
}

TEST_CASE_TEMPLATE("types: inversion.hpp and eigen_backend.hpp — invert and invert_eigen, every option", T, float,
                   double, long double) {
  for (const int length : {0, -13, 9})
    for (const RecurrenceAlgorithm algorithm : {RecurrenceAlgorithm::wheeler, RecurrenceAlgorithm::product_difference})
      for (const EigenSolver solver : {EigenSolver::automatic, EigenSolver::golub_welsch})
        for (const Support support : {Support::positive_half_line, Support::real_line}) {
          INFO("length unit 2^" << length);
          const std::array<T, 6> m = three_atoms<T>(length);
          const InversionOptions options{.algorithm = algorithm, .solver = solver, .support = support};
          const InversionResult<T, 3> fixed = invert<3>(m, options);
          REQUIRE(fixed.status == InversionStatus::ok);
          check_three_atoms(fixed.quadrature, inversion_factor, length);
          CHECK(fixed.boundary_distance > T(0));
          const InversionResult<T, 5> spare = invert<T, 5>(std::span<const T>(m), options);  // capacity 5, 3 nodes
          REQUIRE(spare.status == InversionStatus::ok);
          check_three_atoms(spare.quadrature, inversion_factor, length);
          const InversionResult<T, 3> eigen = invert_eigen<3>(m, options);
          REQUIRE(eigen.status == InversionStatus::ok);
          check_three_atoms(eigen.quadrature, inversion_factor, length);
          CHECK(invert_eigen<T, 4>(std::span<const T>(m), options).quadrature.size == 3);
        }
  // Four atoms: QL for every type (measured within 251 ε in float, 240 ε in double, 553 ε in long
  // double; 4096 ε leaves a factor 7).
  const std::array<T, 8> m = four_atoms<T>();
  const InversionResult<T, 4> r = invert<4>(m);
  REQUIRE(r.status == InversionStatus::ok);
  const T x[4] = {1, 2, 4, 8}, w[4] = {0.125, 0.375, 0.375, 0.125};
  for (int i = 0; i < 4; ++i) {
    CHECK(close(r.quadrature.nodes[std::size_t(i)], x[i], 4096));
    CHECK(close(r.quadrature.weights[std::size_t(i)], w[i], 4096, T(1)));
  }
}

TEST_CASE_TEMPLATE("types: realizability.hpp — counts, ζ, log-convexity and Hankel determinants", T, float, double,
                   long double) {
  using std::exp;
  using std::log;
  const int length = -13;
  const std::array<T, 6> m = three_atoms<T>(length);
  const RealizabilityReport<T, 3> r = realizability<T, 3>(std::span<const T>(m));
  REQUIRE(r.status == InversionStatus::ok);
  CHECK(r.realizable_nodes == 3);
  CHECK(r.zeta_count == 5);
  CHECK(close(r.zeta[4], T(std::ldexp(ratio<T>(19, 13), length))));
  CHECK(r.log_convex);
  // ln m_k − 2 ln m_{k+1} + ln m_{k+2} = ln(m_k m_{k+2}/m_{k+1}²), unit-free: k = 0 gives ln(100/81).
  CHECK(close(r.log_second_differences[0], T(log(ratio<T>(100, 81)))));
  // H_k: H_{2i} ∝ L^{i(i+1)}, H_{2i+1} ∝ L^{(i+1)²}.
  const long long hankel[6][2] = {{1, 1}, {9, 4}, {19, 16}, {13, 2}, {9, 8}, {9, 1}};
  REQUIRE(r.hankel_count == 6);
  CHECK(r.hankel_positive);
  for (int k = 0; k < 6; ++k) {
    const int i = k / 2, power = k % 2 == 0 ? i * (i + 1) : (i + 1) * (i + 1);
    const T expected = log(ratio<T>(hankel[k][0], hankel[k][1])) + T(power * length) * log(T(2));
    CHECK(r.hankel_sign[std::size_t(k)] == 1);
    CHECK(close(r.log_abs_hankel[std::size_t(k)], expected, 64, T(1) + std::abs(expected)));
  }
  // The boundary set of issue 13 in a form every type holds exactly: {1, 0, 2^-26, 0},
  // H_2 = 2^-26 and H_3 = −2^-52, where ζ_1 = 0 and ζ_2 = ∞.
  const std::array<T, 4> boundary{T(1), T(0), std::ldexp(T(1), -26), T(0)};
  const RealizabilityReport<T, 2> b = realizability<T, 2>(std::span<const T>(boundary));
  CHECK(b.status == InversionStatus::not_realizable);
  REQUIRE(b.hankel_count == 4);
  CHECK(b.hankel_sign[1] == 0);
  CHECK(b.hankel_sign[2] == 1);
  CHECK(b.hankel_sign[3] == -1);
  CHECK(close(b.log_abs_hankel[2], T(-26) * log(T(2))));
  CHECK(close(b.log_abs_hankel[3], T(-52) * log(T(2))));
}

TEST_CASE_TEMPLATE("types: adaptive.hpp — thresholds, invert_adaptive, gauss_radau", T, float, double, long double) {
  using std::cbrt;
  using std::sqrt;
  const T eps = std::numeric_limits<T>::epsilon();
  CHECK(close(default_degeneracy_threshold<T>(), T(cbrt(eps)), 4));
  CHECK(close(default_boundary_tolerance<T>(), T(cbrt(eps) * cbrt(eps)), 8));
  // The three atoms given 6 moments: all three; given them twice over (coincident pairs merged,
  // 6 moments of two atoms at 1 and 4, weights 1/2): two nodes.
  const std::array<T, 6> m = three_atoms<T>();
  const AdaptiveInversionResult<T, 3> all = invert_adaptive<3>(m);
  CHECK(all.status == InversionStatus::ok);
  check_three_atoms(all.quadrature, inversion_factor);
  std::array<T, 6> two{};
  for (int k = 0; k < 6; ++k) two[std::size_t(k)] = T(0.5) + T(0.5) * std::pow(T(4), T(k));
  const AdaptiveInversionResult<T, 3> merged = invert_adaptive<3>(two);
  CHECK(merged.status == InversionStatus::reduced);
  REQUIRE(merged.quadrature.size == 2);
  CHECK(close(merged.quadrature.nodes[0], T(1), inversion_factor));
  CHECK(close(merged.quadrature.nodes[1], T(4), inversion_factor));
  // Gauss–Radau, fixed node 0, from the 5 moments 1/(k + 1) of uniform 0 to 1: nodes 0,
  // (6 ∓ √6)/10, weights 1/9, (16 ± √6)/36 (the 3-point Radau rule of [−1, 1] mapped).
  std::array<T, 5> uniform{};
  for (int k = 0; k < 5; ++k) uniform[std::size_t(k)] = T(1) / T(k + 1);
  const T root6 = sqrt(T(6));
  const T nodes[3] = {T(0), (T(6) - root6) / T(10), (T(6) + root6) / T(10)};
  const T weights[3] = {T(1) / T(9), (T(16) + root6) / T(36), (T(16) - root6) / T(36)};
  const InversionResult<T, 3> radau = gauss_radau<T, 3>(std::span<const T>(uniform), T(0));
  REQUIRE(radau.status == InversionStatus::ok);
  AdaptiveOptions<T> options;
  options.radau = true;
  const AdaptiveInversionResult<T, 3> adaptive = invert_adaptive<T, 3>(std::span<const T>(uniform), options);
  REQUIRE(adaptive.radau);
  for (const Quadrature<T, 3>& q : {radau.quadrature, adaptive.quadrature}) {
    REQUIRE(q.size == 3);
    for (int i = 0; i < 3; ++i) {
      CHECK(close(q.nodes[std::size_t(i)], nodes[i], 64, T(1)));
      CHECK(close(q.weights[std::size_t(i)], weights[i], 64, T(1)));
    }
  }
}

TEST_CASE_TEMPLATE("types: correction.hpp — McGraw, the log-normal fill, the monodisperse fill", T, float, double,
                   long double) {
  using std::exp;
  // A log-normal set (m_0 = 1/2, median 1, s² = 1/4): m_k = exp(k²/8)/2, untouched by both.
  std::array<T, 8> lognormal{};
  lognormal_moments(T(0.5), LognormalParameters<T>{T(0), T(0.25)}, std::span<T>(lognormal));
  for (const CorrectionResult<T, 4>& r :
       {correct_moments<T, 4>(std::span<const T>(lognormal)), mcgraw_correct<T, 4>(std::span<const T>(lognormal))}) {
    CHECK(r.status == CorrectionStatus::unchanged);
    CHECK(r.realizable_moments == 8);
  }
  // The three atoms with m_5 halved (not realizable: ζ_5 < 0): corrected to a realizable set
  // that keeps m_0 … m_4 as McGraw leaves them.
  std::array<T, 6> corrupted = three_atoms<T>();
  corrupted[5] *= T(0.5);
  REQUIRE(realizability<T, 3>(std::span<const T>(corrupted)).status == InversionStatus::reduced);
  const CorrectionResult<T, 3> c = correct_moments<T, 3>(std::span<const T>(corrupted));
  CHECK((c.status == CorrectionStatus::mcgraw || c.status == CorrectionStatus::lognormal));
  CHECK(c.realizable_moments == 6);
  CHECK(c.moments[0] == corrupted[0]);
  // m_0 m_2 < m_1² (1, 2, 3, …): the monodisperse fill m_0 r^k, r = 2: exact.
  const std::array<T, 4> low{T(1), T(2), T(3), T(4)};
  const CorrectionResult<T, 2> mono = correct_moments<T, 2>(std::span<const T>(low));
  CHECK(mono.status == CorrectionStatus::monodisperse);
  for (int k = 0; k < 4; ++k) CHECK(close(mono.moments[std::size_t(k)], std::ldexp(T(1), k), 4));
  // The log-normal fill shares m_0, m_1, m_2: uniform moments 1, 1/2, 1/3 with m_3 := 0 (not
  // realizable, and McGraw needs 6 positive moments) become m_3 = m_0 r³ q³ = (1/8)(64/27) = 8/27
  // (r = m_1/m_0 = 1/2, q = m_0 m_2/m_1² = 4/3).
  const std::array<T, 4> uniform_bad{T(1), T(0.5), T(1) / T(3), T(0)};
  const CorrectionResult<T, 2> filled = correct_moments<T, 2>(std::span<const T>(uniform_bad));
  CHECK(filled.status == CorrectionStatus::lognormal);
  CHECK(close(filled.moments[3], ratio<T>(8, 27), 64));
  CHECK(filled.realizable_moments == 4);
}

TEST_CASE_TEMPLATE("types: batched.hpp — invert_batched = invert per cell, N = 1 … 4", T, float, double, long double) {
  // Per cell and in lanes the recurrence rounds differently where the compiler contracts a*b + c
  // into an FMA in one path only (-march=native); the rules then agree to the conditioning of the
  // set, the factors of the inversion tests above.
  const auto run = [](auto nodes_tag, const auto& set, double factor) {
    constexpr int N = decltype(nodes_tag)::value;
    constexpr std::size_t cells = 37;  // full and partial lanes in every type
    std::vector<std::vector<T>> fields(2 * N, std::vector<T>(cells));
    for (std::size_t c = 0; c < cells; ++c)
      for (int k = 0; k < 2 * N; ++k)  // the same set in units 2^−4 … 2^4
        fields[std::size_t(k)][c] = std::ldexp(set[std::size_t(k)], k * (int(c % 9) - 4));
    std::vector<std::vector<T>> x(N, std::vector<T>(cells)), w(x);
    std::vector<int> sizes(cells);
    std::vector<InversionStatus> status(cells);
    MomentBatch<T, N> in;
    for (int k = 0; k < 2 * N; ++k) in.moments[std::size_t(k)] = fields[std::size_t(k)];
    QuadratureBatch<T, N> out;
    for (int i = 0; i < N; ++i) {
      out.nodes[std::size_t(i)] = x[std::size_t(i)];
      out.weights[std::size_t(i)] = w[std::size_t(i)];
    }
    out.sizes = sizes;
    out.status = status;
    REQUIRE(invert_batched(in, out));
    for (std::size_t c = 0; c < cells; ++c) {
      std::array<T, 2 * N> cell{};
      for (int k = 0; k < 2 * N; ++k) cell[std::size_t(k)] = fields[std::size_t(k)][c];
      const InversionResult<T, N> single = invert<N>(cell);
      INFO("N = " << N << ", cell " << c);
      CHECK(status[c] == single.status);
      CHECK(sizes[c] == N);
      for (int i = 0; i < N; ++i) {
        CHECK(close(x[std::size_t(i)][c], single.quadrature.nodes[std::size_t(i)], factor));
        CHECK(close(w[std::size_t(i)][c], single.quadrature.weights[std::size_t(i)], factor, T(1)));
      }
    }
  };
  run(std::integral_constant<int, 1>{}, std::array<T, 2>{T(1), T(3)}, 4);
  run(std::integral_constant<int, 2>{}, std::array<T, 4>{T(1), ratio<T>(5, 2), ratio<T>(17, 2), ratio<T>(65, 2)},
      inversion_factor);  // atoms 1, 4
  run(std::integral_constant<int, 3>{}, three_atoms<T>(), inversion_factor);
  run(std::integral_constant<int, 4>{}, four_atoms<T>(), 4096);
}

TEST_CASE_TEMPLATE("types: moment_set.hpp — quadrature moments, mean diameters, NDF, log-normal sets", T, float, double,
                   long double) {
  using std::log;
  const std::array<T, 6> expected = three_atoms<T>();
  std::array<T, 6> m{};
  REQUIRE(moments_from_quadrature<T>(atom_nodes<T>, atom_weights<T>, m));
  CHECK(m == expected);  // exact: dyadic sums
  Quadrature<T, 3> q;
  q.nodes = atom_nodes<T>;
  q.weights = atom_weights<T>;
  q.size = 3;
  std::array<T, 6> again{};
  REQUIRE(moments_from_quadrature(q, std::span<T>(again)));
  CHECK(again == expected);
  CHECK(quadrature_moment(q, -1) == ratio<T>(9, 16));
  CHECK(close(d32(q), ratio<T>(16, 9), 4));    // Σφ/Σ(φ/ξ)
  CHECK(close(d10(q), ratio<T>(100, 81), 4));  // M_{−2}/M_{−3} = (25/64)/(81/256)
  CHECK(close(mean_diameter<T>(5, 3, [&](int k) { return quadrature_moment(q, k); }), T(2.5), 4));  // √(M_2/M_0)
  CHECK(d43<T>(m) == ratio<T>(9, 4));
  CHECK(variance<T>(m) == ratio<T>(19, 16));
  CHECK(solid_fraction<T>(m) == T(1));
  const T pi = T(3.14159265358979323846264338327950288L);
  CHECK(close(class_number_density(T(0.5), T(2)), T(3) / (T(8) * pi), 4));  // 6φ/(πξ³) = 3/(8π)
  std::array<T, 6> ndf{}, vdf{};
  REQUIRE(ndf_from_vdf_moments<T>(m, ndf));
  CHECK(close(ndf[1], ratio<T>(27, 2) / pi, 4));  // (6/π) 9/4
  REQUIRE(vdf_from_ndf_moments<T>(ndf, vdf));
  for (int k = 0; k < 6; ++k) CHECK(close(vdf[std::size_t(k)], m[std::size_t(k)], 8));
  // Log-normal: second differences of ln m_k are s², and the matching log-normal of m_0 … m_2
  // is the one they came from.
  std::array<T, 6> lognormal{};
  const LognormalParameters<T> p{T(-0.75), T(0.25)};
  lognormal_moments(T(0.5), p, std::span<T>(lognormal));
  for (int k = 0; k + 2 < 6; ++k) {
    const T second = log(lognormal[std::size_t(k)]) - T(2) * log(lognormal[std::size_t(k + 1)]) +
                     log(lognormal[std::size_t(k + 2)]);
    CHECK(close(second, T(0.25), 64, T(8)));  // the logarithms are up to |ln m_5| ~ 4
  }
  const LognormalParameters<T> back = lognormal_matching(lognormal[0], lognormal[1], lognormal[2]);
  CHECK(close(back.mu, p.mu, 64, T(1)));
  CHECK(close(back.sigma_squared, p.sigma_squared, 64, T(1)));
}

TEST_CASE_TEMPLATE("types: moment_set.hpp — sieve moments, checked, Geldart, d32 and d10 of bins", T, float, double,
                   long double) {
  using std::log;
  // Bins 1–2 and 2–4 with mass fractions 1/4, 3/4 in a bed of voidage 1/2 (the VDF uniform per
  // bin, seed 000 eq. E.7): M_0 = 1/2, M_1 = 21/16, M_2 = 91/24, M_{−1} = 5 ln 2/16, so
  // d32 = 8/(5 ln 2); M_{−2}/M_{−3} = (7/32)/(33/256) = 56/33; Geldart's d_sv = 12/5.
  const std::array<T, 3> edges{T(1), T(2), T(4)};
  const std::array<T, 2> fractions{T(0.25), T(0.75)};
  const SieveAnalysis<T> psd{edges, fractions};
  std::array<T, 3> m{};
  REQUIRE(sieve_moments(psd, T(0.5), std::span<T>(m)));
  CHECK(m[0] == T(0.5));
  CHECK(close(m[1], ratio<T>(21, 16), 8));
  CHECK(close(m[2], ratio<T>(91, 24), 8));
  CHECK(close(sieve_moment(psd, T(0.5), -1), T(5) * log(T(2)) / T(16), 8));
  CHECK(fluidbed::test::same_arithmetic(sieve_moment(psd, T(0.5), 2, fluidbed::checked), m[2]));  // one moment vs the span form
  CHECK_THROWS_AS(sieve_moment(psd, T(1.5), 2, fluidbed::checked), std::domain_error);
  CHECK(close(d32(psd), T(8) / (T(5) * log(T(2))), 8));
  CHECK(close(d10(psd), ratio<T>(56, 33), 8));
  CHECK(close(geldart_sauter_diameter(psd), ratio<T>(12, 5), 8));
  // Number-based fractions 1/4, 3/4 (the NDF uniform per bin): M_1 = (1/2)(1519/20)/(375/16).
  const SieveAnalysis<T> counted{edges, fractions, SizeBasis::number};
  CHECK(close(sieve_moment(counted, T(0.5), 1), ratio<T>(3038, 1875), 16));
}

TEST_CASE_TEMPLATE("types: dqmom.hpp and dqmom_batched.hpp — growth identities, batched and any orders",
                   T, float, double, long double) {
  // Nodes 1/8, 1/4, 3/8 (m; the scale is a power of two, exact), dyadic weights and growth rates:
  // the growth identities c^a = 3φG/ξ, c^ξ = 4φG are exact rationals rounded once.
  const std::array<T, 3> xi{T(0.125), T(0.25), T(0.375)}, phi{T(0.25), T(0.125), T(0.5)}, g{T(1), T(-2), T(0.5)};
  const std::span<const T> x(xi), w(phi), rate(g);
  const dqmom::System<T, 3> system{x, w};
  REQUIRE(system.size() == 3);
  const auto terms = dqmom::growth_terms<T, 3>(dqmom::Weights::volume_fraction, w, x, rate);
  const auto c = system.solve(std::span<const dqmom::PointSource<T>>(terms));
  for (int i = 0; i < 3; ++i) {
    CHECK(close(c.weight[i], T(3) * phi[i] * g[i] / xi[i], 64));
    CHECK(close(c.weighted_node[i], T(4) * phi[i] * g[i], 64));
  }
  // The same as moment sources, through System, solve_batched (its κ too) and solve_orders:
  // within the measured ε κ of the moment form.
  const std::array<T, 6> orders{T(0), T(1), T(2), T(3), T(4), T(5)};
  const auto s = dqmom::growth_moment_sources(dqmom::Weights::volume_fraction, w, x, rate, orders);
  const auto moments = system.solve(std::span<const T>(s));
  const auto any = dqmom::solve_orders<T, 3>(x, w, std::span<const T>(orders), std::span<const T>(s));
  const T tolerance = T(16) * std::numeric_limits<T>::epsilon() * system.condition();
  std::array<std::array<T, 1>, 3> nodes{}, weights{}, a{}, b{};
  std::array<std::array<T, 1>, 6> sources{};
  std::array<dqmom::SourceStatus, 1> status{};
  std::array<T, 1> condition{};
  dqmom::SourceBatch<T, 3> batch;
  for (int i = 0; i < 3; ++i) {
    nodes[i][0] = xi[i], weights[i][0] = phi[i];
    batch.nodes[i] = nodes[i], batch.weights[i] = weights[i], batch.weight_sources[i] = a[i];
    batch.weighted_node_sources[i] = b[i];
  }
  for (int k = 0; k < 6; ++k) sources[k][0] = s[k], batch.moment_sources[k] = sources[k];
  batch.status = status;
  batch.condition = condition;
  dqmom::solve_batched(batch);
  CHECK(status[0] == dqmom::SourceStatus::ok);
  CHECK(close(condition[0], system.condition(), 64));
  for (int i = 0; i < 3; ++i)
    for (const auto& [got_a, got_b] : {std::pair{moments.weight[i], moments.weighted_node[i]},
                                       std::pair{any.weight[i], any.weighted_node[i]}, std::pair{a[i][0], b[i][0]}}) {
      CHECK(std::abs(got_a - c.weight[i]) <= tolerance * T(24));  // |c^a| <= 24
      CHECK(std::abs(got_b - c.weighted_node[i]) <= tolerance * T(1));
    }
  // Diffusion as moments and as functionals; number sources as volume sources.
  const std::array<T, 3> intensity{T(1), T(0.5), T(0.25)};
  const auto sd = dqmom::diffusion_sources<T, 3>(x, std::span<const T>(intensity));
  const auto dt = dqmom::diffusion_terms<T, 3>(x, std::span<const T>(intensity));
  const auto by_moments = system.solve(std::span<const T>(sd));
  const auto by_terms = system.solve(std::span<const dqmom::PointSource<T>>(dt));
  for (int i = 0; i < 3; ++i) CHECK(std::abs(by_moments.weight[i] - by_terms.weight[i]) <= tolerance * T(4096));
  const auto volume = dqmom::volume_sources_from_number(c, x, T(1));
  CHECK(close(volume.weight[0], T(3) * xi[0] * xi[0] * c.weighted_node[0] - T(2) * xi[0] * xi[0] * xi[0] * c.weight[0], 16));
  // Transport pieces.
  const auto p = dqmom::moment_velocity_coefficients<T, 3>(w, x, T(2));
  CHECK(close(p[0] + p[1] + p[2], T(1), 8));
  const std::array<T, 3> u{T(1), T(1), T(1)};
  CHECK(close(dqmom::moment_velocity<T, 3>(w, x, std::span<const T>(u), T(3)), T(1), 8));
  CHECK(close(dqmom::upwind_moment_flux(w, x, w, x, std::span<const T>(u), T(0)), T(0.875), 8));
  CHECK(dqmom::upwind_numerical_diffusivity(T(2), T(0.5)) == T(0.5));
  CHECK(dqmom::diffusion_intensity(T(2), T(0.5), T(0.25)) == T(0.25));
  std::array<T, 6> m{};
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 3; ++i) m[k] += phi[i] * std::pow(xi[i], T(k));
  const auto state = dqmom::state_from_moments<T, 3>(std::span<const T>(m));
  REQUIRE(state.size == 3);
  const auto back = dqmom::nodes_of<T, 3>(state, std::array<T, 3>{});
  for (int i = 0; i < 3; ++i) CHECK(close(back[i], xi[i], 4096));  // the inversion's conditioning
}
