// fluidbed — from moments to the three-term recurrence (the Jacobi matrix): Wheeler's
// algorithm and Gordon's product-difference algorithm, with exact power-of-two scaling.
//
// Notation (seed 000 §5.7.2 and App. C):
//   moments    m_k = ∫ x^k f(x) dx, k = 0 … 2n−1 (raw, dimensional, unnormalised)
//   recurrence p_{k+1}(x) = (x − α_k) p_k(x) − β_k p_{k−1}(x), p_0 = 1, p_{−1} = 0
//   Jacobi matrix J_n = tridiag(√β_k; α_k; √β_k); its eigenvalues are the n Gauss nodes
//   and the weights are m_0 times the squared first components of its unit eigenvectors.
//   Stieltjes coefficients ζ_k (seed 000's ς_k): ζ_1 = α_0, β_k = ζ_{2k−1} ζ_{2k},
//   α_k = ζ_{2k} + ζ_{2k+1}. A moment set is realizable by a measure on [0, ∞) with n
//   points of increase iff ζ_1 … ζ_{2n−1} > 0; on the whole line iff β_1 … β_{n−1} > 0.
//
// Scale invariance. Both algorithms run on moments scaled by exact powers of two:
//   m̃_k = m_k / (2^a 2^(k b)),  2^a ≈ m_0,  2^b ≈ m_1/m_0 (or √(m_2/m_0) for zero mean),
// and the outputs are unscaled exactly (α·2^b, β·2^(2b), m_0·2^a). Scaling by a power of
// two changes no mantissa bit, so the same distribution in metres and in micrometres gives
// the same recurrence to the last bits, and every threshold is relative by construction.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

#include "../core/config.hpp"

namespace fluidbed::moments {

// The support a moment set is tested against.
enum class Support {
  positive_half_line,  // [0, ∞): sizes, masses (Stieltjes problem); needs every ζ_k > 0
  real_line,           // (−∞, ∞): velocities (Hamburger problem); needs every β_k > 0
};

// Exact power-of-two scales of a moment set: m_k = 2^(weight_exponent + k·length_exponent) m̃_k.
struct MomentScaling {
  int weight_exponent = 0;
  int length_exponent = 0;
};

// Recurrence coefficients of the first `size` nodes (size <= N), in the caller's units.
// beta[0] holds m_0 (Gautschi's convention), so beta[0..size−1] and alpha[0..size−1] are
// the whole Jacobi matrix plus the total weight. Entries beyond `size` are diagnostics of
// an early stop (see the algorithms), not part of the matrix.
template <class T, int N>
struct Recurrence {
  std::array<T, N> alpha{};
  std::array<T, N> beta{};
  int size = 0;
};

namespace detail {

using fluidbed::detail::is_normal;

// IEEE binary64/binary32: exponents are read from, and powers of two written into, the
// exponent field (a per-cell library call to frexp/ldexp costs more than Wheeler's whole
// arithmetic at n = 3). Other types (long double, multiprecision) use frexp/ldexp.
template <class T>
inline constexpr bool has_binary_layout =
    std::numeric_limits<T>::is_iec559 && (sizeof(T) == sizeof(std::uint64_t) || sizeof(T) == sizeof(std::uint32_t));

template <class T>
using layout_bits = std::conditional_t<sizeof(T) == sizeof(std::uint64_t), std::uint64_t, std::uint32_t>;

// 2^e, exactly; 0 or ∞ where 2^e is not a normal number.
template <class T>
FLUIDBED_HOST_DEVICE T power_of_two(int e) {
  if constexpr (has_binary_layout<T>) {
    constexpr int max_exponent = std::numeric_limits<T>::max_exponent - 1;  // 1023 or 127
    if (e > max_exponent) return std::numeric_limits<T>::infinity();
    if (e < 1 - max_exponent) return T(0);
    using bits = layout_bits<T>;
    return std::bit_cast<T>(bits(e + max_exponent) << (std::numeric_limits<T>::digits - 1));
  } else {
    using std::ldexp;
    return ldexp(T(1), e);
  }
}

// For a binary layout: the biased exponent of the power of two nearest |x|, read from the bits of
// a normal x = ±2^E · 1.f: the exponent field, plus one when 1.f >= √2. 0 for a zero or subnormal
// x (no exponent field to read), beyond the largest field for ±∞ and NaN. The batched lanes
// (batched.hpp) read their scales with it, branch-free.
template <class T>
FLUIDBED_HOST_DEVICE constexpr int nearest_biased_exponent(const T& x) {
  using bits = layout_bits<T>;
  constexpr int shift = std::numeric_limits<T>::digits - 1;
  constexpr bits field_mask = bits(2 * (std::numeric_limits<T>::max_exponent - 1) + 1);
  constexpr bits fraction_mask = (bits(1) << shift) - 1;
  constexpr bits root_two = std::bit_cast<bits>(T(1.41421356237309504880)) & fraction_mask;
  const bits b = std::bit_cast<bits>(x);
  const int field = int((b >> shift) & field_mask);
  return field == 0 ? 0 : field + int((b & fraction_mask) >= root_two);
}

// The nearest integer to log2(x) for x > 0 finite.
template <class T>
FLUIDBED_HOST_DEVICE int nearest_power_of_two_exponent(const T& x) {
  if constexpr (has_binary_layout<T>) {
    if (is_normal(x)) return nearest_biased_exponent(x) - (std::numeric_limits<T>::max_exponent - 1);
  }
  using std::frexp;
  int e = 0;
  const T f = frexp(x, &e);  // x = f 2^e, f in [0.5, 1)
  return f < T(0.70710678118654752440) ? e - 1 : e;
}

}  // namespace detail

// The scaling that brings m_0 and the length scale of the set to O(1). The length scale is
// the larger of |m_1|/m_0 and √(m_2/m_0) (for a realizable set on either support the latter,
// which keeps m̃_2 = 1 and every m̃_k, k >= 2, >= 1 on [0, ∞): the mean alone would put a
// broad set's high moments, or a real-line set with a tiny mean, out of range), 1 without
// either. It is read from the exponents of the moments, never from their ratios, which over-
// or underflow for sets spanning the range ({2.9e61, 2.8e-279, 5.6e-188}); so a change of
// units by powers of two changes it by exactly those powers. Any power of two near the
// length scale serves: every step of the pipeline commutes exactly with such a scaling.
// Total: the identity scaling {0, 0} for an empty set or one whose m_0 is not > 0 and finite
// (which no entry point scales: they report it first), and a moment m_1 or m_2 that is not
// finite gives no length scale.
template <class T>
FLUIDBED_HOST_DEVICE MomentScaling scaling_of(std::span<const T> m) {
  using std::abs;
  using std::isfinite;
  MomentScaling s;
  if (m.empty() || !(m[0] > T(0)) || !isfinite(m[0])) return s;
  s.weight_exponent = detail::nearest_power_of_two_exponent(m[0]);
  constexpr int none = std::numeric_limits<int>::min();
  const auto gives_scale = [&](std::size_t k) { return m.size() > k && m[k] != T(0) && isfinite(m[k]); };
  const int from_mean =
      gives_scale(1) ? detail::nearest_power_of_two_exponent(abs(m[1])) - s.weight_exponent : none;
  // ⌈e/2⌉ for the exponent e of m_2/m_0, as a shift: (e + 1) >> 1 rounds toward −∞ for e < 0 too.
  const int from_second =
      gives_scale(2) && m[2] > T(0) ? (detail::nearest_power_of_two_exponent(m[2]) - s.weight_exponent + 1) >> 1
                                    : none;
  const int length = from_mean > from_second ? from_mean : from_second;
  s.length_exponent = length == none ? 0 : length;
  return s;
}

namespace detail {

// Whether the first `size` entries of two arrays (α and β, or nodes and weights) are finite.
template <class T, std::size_t N>
FLUIDBED_HOST_DEVICE bool finite_prefix(const std::array<T, N>& a, const std::array<T, N>& b, int size) {
  using std::isfinite;
  for (int i = 0; i < size; ++i)
    if (!isfinite(a[std::size_t(i)]) || !isfinite(b[std::size_t(i)])) return false;
  return true;
}

// Whether a set could be brought to O(1): every scaled moment finite (a distribution so broad
// that m̃_{2n−1} overflows spans more than the floating-point range) and m̃_1 a normal number
// unless m_1 = 0 (a mean below the range relative to the spread, which sets the length scale, would be
// rounded to a few bits or to 0: a positive set would lose its mean, ζ_1 = m̃_1/m̃_0). Every
// entry point reports such a set as invalid_input.
template <class T>
FLUIDBED_HOST_DEVICE bool scaled_moments_in_range(std::span<const T> m, std::span<const T> scaled) {
  using std::isfinite;
  for (const T& x : scaled)
    if (!isfinite(x)) return false;
  return m.size() < 2 || m[1] == T(0) || is_normal(scaled[1]);
}

}  // namespace detail

namespace detail {

// x · 2^e, rounded as ldexp(x, e) rounds. A product with a normal power of two is that same
// correctly rounded value, and much cheaper than ldexp; `power` = 2^e precomputed by the
// caller (0 or ∞ when 2^e is not a normal number, which only a set spanning the whole
// floating-point range produces: then ldexp itself is used).
template <class T>
FLUIDBED_HOST_DEVICE T times_power_of_two(const T& x, const T& power, int e) {
  using std::ldexp;
  return is_normal(power) ? x * power : ldexp(x, e);
}

}  // namespace detail

namespace detail {

// Every entry of `out` NaN: what the functions that fill a caller's span leave there when the
// span sizes do not match (they also return false), so that ignoring the failure cannot go
// unnoticed downstream (NaN moments are invalid_input for every inversion).
template <class T>
FLUIDBED_HOST_DEVICE void fill_with_nan(std::span<T> out) {
  for (T& x : out) x = std::numeric_limits<T>::quiet_NaN();
}

// The parity a moment count must have.
enum class Parity { any, even, odd };

// Whether an entry point that takes `lowest` … `highest` moments of the given parity takes
// `count` of them. Every entry point that takes a span of moments checks its count so, at every
// optimisation level, before it reads an element: a count it does not take is a status (or an
// empty result), never an access beyond its storage and never a moment silently dropped.
FLUIDBED_HOST_DEVICE constexpr bool count_within(std::size_t count, std::size_t lowest, std::size_t highest,
                                                 Parity parity = Parity::any) {
  const bool parity_ok = parity == Parity::any || (count % 2 == 0) == (parity == Parity::even);
  return count >= lowest && count <= highest && parity_ok;
}

// Whether the size of a Recurrence or a Quadrature is one its storage holds: 0 … N. Every
// function taking one treats another size (no function of the library makes one) as no rule.
template <template <class, int> class Rule, class T, int N>
FLUIDBED_HOST_DEVICE constexpr bool size_in_storage(const Rule<T, N>& r) {
  return r.size >= 0 && r.size <= N;
}

}  // namespace detail

// m̃_k = m_k 2^−(a + k b), k < m.size(), exactly (the factors 2^−(a + k b) are exact running
// products) into the first m.size() entries of `scaled`. Returns false, with every entry of
// `scaled` NaN, if `scaled` has fewer entries than m.
template <class T>
FLUIDBED_HOST_DEVICE bool scale_moments(std::span<const T> m, MomentScaling s, std::span<T> scaled) {
  if (scaled.size() < m.size()) {
    detail::fill_with_nan(scaled);
    return false;
  }
  const T step = detail::power_of_two<T>(-s.length_exponent);
  T factor = detail::power_of_two<T>(-s.weight_exponent);
  for (std::size_t k = 0; k < m.size(); ++k) {
    const int e = -(s.weight_exponent + int(k) * s.length_exponent);
    scaled[k] = detail::times_power_of_two(m[k], factor, e);
    factor *= step;
  }
  return true;
}

namespace detail {

// m_0 … m_{size−1} scaled by scaling_of(m) (scale_moments), in value-initialized storage for the
// 2N moments of an N-node entry point (entries from size on are 0). The callers check the count
// first; one above 2N gives size 0.
template <class T, int N>
struct ScaledMoments {
  std::array<T, 2 * N> values{};
  std::size_t size = 0;
  MomentScaling scaling;
  FLUIDBED_HOST_DEVICE std::span<const T> view() const { return std::span<const T>(values.data(), size); }
};

template <class T, int N>
FLUIDBED_HOST_DEVICE ScaledMoments<T, N> scaled_moments(std::span<const T> m) {
  ScaledMoments<T, N> s;
  if (m.size() > s.values.size()) return s;
  s.size = m.size();
  s.scaling = scaling_of(m);
  scale_moments(m, s.scaling, std::span<T>(s.values.data(), s.size));
  return s;
}

}  // namespace detail

// Undoes scale_moments on a recurrence: α·2^b, β_k·2^(2b) (k >= 1), β_0 = m_0·2^a. A
// recurrence whose size is not within 0 … N is left unchanged.
template <class T, int N>
FLUIDBED_HOST_DEVICE void unscale(Recurrence<T, N>& r, MomentScaling s) {
  using std::ldexp;
  if (!detail::size_in_storage(r)) return;
  for (int k = 0; k < r.size; ++k) {
    r.alpha[k] = ldexp(r.alpha[k], s.length_exponent);
    r.beta[k] = ldexp(r.beta[k], k == 0 ? s.weight_exponent : 2 * s.length_exponent);
  }
}

namespace detail {

// Operations on a lane value V: a scalar T (one cell) here; batched.hpp specialises it for
// Eigen arrays of L cells. The Wheeler kernel below and the three-node solver of jacobi_eigen.hpp are written
// once against it.
template <class V>
struct lane_ops {
  using scalar = V;
  FLUIDBED_HOST_DEVICE static V sqrt(const V& x) {
    using std::sqrt;
    return sqrt(x);
  }
  FLUIDBED_HOST_DEVICE static V abs(const V& x) {
    using std::abs;
    return abs(x);
  }
  FLUIDBED_HOST_DEVICE static V min(const V& x, const scalar& bound) { return bound < x ? V(bound) : x; }
  FLUIDBED_HOST_DEVICE static V constant(const scalar& c) { return c; }
  // The larger of two error estimates (accuracy.hpp), +∞ where `next` is NaN or +∞.
  FLUIDBED_HOST_DEVICE static V larger_error(const V& so_far, const V& next) {
    if (!(next <= std::numeric_limits<V>::max())) return std::numeric_limits<V>::infinity();
    return next > so_far ? next : so_far;
  }
  // +1 or −1 (+1 for zero).
  FLUIDBED_HOST_DEVICE static V sign(const V& x) { return x < V(0) ? V(-1) : V(1); }
  // a where s > 0, else b (s is a sign from sign()).
  FLUIDBED_HOST_DEVICE static V choose(const V& s, const V& a, const V& b) { return s > V(0) ? a : b; }
};

// Wheeler's levels 0 … n−1 on V, a scalar or a lane of cells (batched.hpp), without an early
// stop: a level whose b_k is not positive leaves non-finite values in the later ones, which
// the callers discard. One division per level (1/σ_{k,k} is reused by the next level).
template <class V, int N>
FLUIDBED_HOST_DEVICE void wheeler_levels(const V* m, int n, V* alpha, V* beta) {
  V sigma[3][2 * N];  // σ_{k−2,·}, σ_{k−1,·}, σ_{k,·} in rotation
  for (int l = 0; l < 2 * n; ++l) sigma[0][l] = m[l];
  beta[0] = m[0];
  using S = typename lane_ops<V>::scalar;
  V inverse_previous = S(1) / m[0];  // 1/σ_{k−1,k−1}
  alpha[0] = m[1] * inverse_previous;
  for (int k = 1; k < n; ++k) {
    const V* previous = sigma[(k + 1) % 3];
    const V* current = sigma[(k + 2) % 3];
    V* next = sigma[k % 3];
    for (int l = k; l < 2 * n - k; ++l) {
      if (k > 1)
        next[l] = current[l + 1] - alpha[k - 1] * current[l] - beta[k - 1] * previous[l];
      else  // σ_{−1,·} = 0
        next[l] = current[l + 1] - alpha[k - 1] * current[l];
    }
    const V inverse_current = S(1) / next[k];
    beta[k] = next[k] * inverse_previous;
    alpha[k] = next[k + 1] * inverse_current - current[k] * inverse_previous;
    inverse_previous = inverse_current;
  }
}

}  // namespace detail

// Wheeler (1974), Rocky Mountain J. Math. 4, 287–296, doi:10.1216/RMJ-1974-4-2-287, with
// ordinary moments (the modified-moment coefficients zero); seed 003 ref. 43, described in
// neither seed:
//   σ_{−1,l} = 0, σ_{0,l} = m_l;  a_0 = m_1/m_0
//   σ_{k,l} = σ_{k−1,l+1} − a_{k−1} σ_{k−1,l} − b_{k−1} σ_{k−2,l},  l = k … 2n−k−1
//   a_k = σ_{k,k+1}/σ_{k,k} − σ_{k−1,k}/σ_{k−1,k−1},  b_k = σ_{k,k}/σ_{k−1,k−1}
// (σ_{k,l} = ∫ x^l p_k dμ; a_k, b_k are the α_k, β_k of product-difference, as the tests check).
// Computes the n = m.size()/2 levels of 2n moments, 1 <= n <= N, on the moments as given (no
// scaling; see recurrence() for the scaled entry point). result.size is the first k with
// b_k <= 0 or not finite (the set is not realizable on the real line beyond k nodes), and
// beta[k] holds that b_k; n when every b_k passes. Another count (odd, 0, above 2N) gives an
// empty recurrence (size 0) without reading m.
template <class T, int N>
FLUIDBED_HOST_DEVICE Recurrence<T, N> wheeler_unscaled(std::span<const T> m) {
  using std::isfinite;
  Recurrence<T, N> r;
  if (!detail::count_within(m.size(), 2, 2 * N, detail::Parity::even)) return r;
  const int n = int(m.size() / 2);
  detail::wheeler_levels<T, N>(m.data(), n, r.alpha.data(), r.beta.data());
  r.size = n;
  for (int k = 1; k < n; ++k)
    if (!(r.beta[k] > T(0)) || !isfinite(r.beta[k])) {
      r.size = k;
      break;
    }
  return r;
}

// The Stieltjes coefficients ζ_1 … ζ_{2n−1} of a recurrence (ζ_1 = α_0, ζ_{2k} = β_k/ζ_{2k−1},
// ζ_{2k+1} = α_k − ζ_{2k}); zeta[j−1] holds ζ_j. A zero ζ makes the following ones undefined
// (±∞ or NaN): realizability tests stop at the first ζ <= 0. All 0 for a recurrence of size 0
// (or a size not within 0 … N).
template <class T, int N>
FLUIDBED_HOST_DEVICE std::array<T, 2 * N> stieltjes_coefficients(const Recurrence<T, N>& r) {
  std::array<T, 2 * N> zeta{};
  if (r.size < 1 || !detail::size_in_storage(r)) return zeta;
  zeta[0] = r.alpha[0];
  for (int k = 1; k < r.size && k < N; ++k) {  // k < N follows from size <= N; GCC 12 -O3 needs it said
    zeta[2 * k - 1] = r.beta[k] / zeta[2 * k - 2];
    zeta[2 * k] = r.alpha[k] - zeta[2 * k - 1];
  }
  return zeta;
}

namespace detail {

// u/(a b) with the roundings of that expression (unless the result is subnormal) but no
// intermediate over- or underflow: the mantissas are divided, the exponents added apart.
// ±∞ or NaN for a or b = 0.
template <class T>
FLUIDBED_HOST_DEVICE T quotient_of_product(const T& u, const T& a, const T& b) {
  using std::frexp;
  using std::ldexp;
  int eu = 0, ea = 0, eb = 0;
  const T mu = frexp(u, &eu), ma = frexp(a, &ea), mb = frexp(b, &eb);
  return ldexp(mu / (ma * mb), eu - ea - eb);
}

}  // namespace detail

// Gordon's product-difference algorithm: Gordon (1968), J. Math. Phys. 9, 655–663,
// doi:10.1063/1.1664624; McGraw (1997), Aerosol Sci. Technol. 27, 255–265,
// doi:10.1080/02786829708965471; seed 000 eqs. 5.87–5.91. Seed eq. 5.88 prints
// "g_{p,2ν+1} = 0" for the last entry of the second column; it is g_{2ν+1,2} = 0 (the matrix
// is (2ν+1)²; so corrected, the algorithm gives Wheeler's α_k, β_k, which the 60-digit generator
// tests/reference/moments_reference.py checks). The first row of the matrix G gives
//   ζ_k = g_{1,k+2} / (g_{1,k+1} g_{1,k}),  k = 1 … 2n−1,
// then α_k = ζ_{2k} + ζ_{2k+1} (ζ_0 = 0) and β_k = ζ_{2k} ζ_{2k−1} (eq. 5.91; β without the
// square root, which the Jacobi matrix takes).
//
// Why textbook PD fails, and the fix. The first-row entries are products of Hankel
// determinants whose decimal exponents grow like Fibonacci numbers: in SI units (sizes
// ~1e-4 m) they leave the double range from n = 5 (for gamma(2.5, θ = 1e-4 m) the decimal
// exponents of the first row run 0, 0, −4, −8, −15, −26, −44, −74, −121, −198, −322 over
// columns 1 … 11: column 11, which n = 5 needs, is below the normal range). Each column q is
// therefore stored as c_q 2^(E_q) with c_q renormalised by an exact power of two r_q after it
// is formed. Since column q is bilinear in columns q−1 and q−2, E_q = E_{q−1} + E_{q−2} + r_q,
// and the ratio above needs only r_{k+2}: ζ_k = c_{1,k+2}/(c_{1,k+1} c_{1,k}) · 2^(r_{k+2}).
// No exponent ever leaves the range, at any n, and the arithmetic is otherwise identical.
// Only the last two columns are kept (O(n) storage, O(n²) work). Two limits remain, for sets
// whose scaled moments themselves span much of the range: ζ_{q−2} is taken from column q as
// formed, in mantissas and exponents (quotient_of_product), since its first entry may be
// below the range once the column is renormalised by its largest one; and an entry pushed below
// the normal range by that shift is lost to every later column, so the next ζ is NaN there and
// the recurrence stops (a reduced rule, as below).
//
// Where it stops. The ζ are computed up to the first one that is not finite: a ζ_j <= 0 is no
// reason to stop, since on the real line ζ_j < 0 is legitimate (N(1/2, 1) has ζ_3 = −3/2) and on
// [0, ∞) the realizability scan finds it. The recurrence is built from them exactly as far as
// Wheeler's would go (every β_k > 0 and finite), and only while every α_k is finite too.
// PD divides by g_{1,k}, so an exact ζ_j = 0 (g_{1,j+2} = 0) leaves every later ζ undefined.
// For j = 2k that is β_k = 0, the boundary of moment space, where Wheeler stops as well; for
// j = 2k + 1 — a zero mean (ζ_1 = m_1/m_0), which any symmetric set on the real line has —
// β_{k+1} = ζ_{2k+1} ζ_{2k+2} = 0·∞ is undefined although the set may be realizable: PD then
// stops after k + 1 levels with beta[k+1] NaN (invert() reports a reduced rule with that NaN as
// the failing value), where Wheeler, which divides by σ_{k,k} ∝ H_{2k} > 0, goes on. Near such
// a set α_{k+1} = ζ_{2k+2} + ζ_{2k+3} cancels two large ζ of opposite sign. Wheeler's algorithm
// is therefore the one for the real line. Computes the n = m.size()/2 levels of 2n moments,
// 1 <= n <= N, on the moments as given; another count gives an empty recurrence (size 0, and
// *zeta_out all 0) without reading m.
template <class T, int N>
FLUIDBED_HOST_DEVICE Recurrence<T, N> product_difference_unscaled(std::span<const T> m,
                                                                 std::array<T, 2 * N>* zeta_out = nullptr) {
  using std::abs;
  using std::frexp;
  using std::isfinite;
  using std::ldexp;
  if (!detail::count_within(m.size(), 2, 2 * N, detail::Parity::even)) {
    if (zeta_out) *zeta_out = {};
    return {};
  }
  const int n = int(m.size() / 2);
  constexpr int R = 2 * N + 1;
  const int rows = 2 * n + 1;
  T before[R]{};  // column q−2
  T last[R]{};    // column q−1
  before[0] = T(1);
  for (int p = 0; p < 2 * n; ++p) last[p] = (p % 2 == 0) ? m[p] : T(-m[p]);
  std::array<T, 2 * N> zeta{};
  T first_row[2] = {before[0], last[0]};  // g_{1,q−2}, g_{1,q−1} (renormalised)
  for (int q = 3; q <= rows; ++q) {
    T column[R]{};
    T largest(0);
    for (int p = 0; p <= rows - q; ++p) {
      column[p] = last[0] * before[p + 1] - before[0] * last[p + 1];
      if (abs(column[p]) > largest) largest = abs(column[p]);
    }
    // ζ_{q−2} from the column as formed, before it is renormalised (see below).
    const T z = detail::quotient_of_product(column[0], first_row[1], first_row[0]);
    zeta[q - 3] = z;
    if (!isfinite(z)) break;  // the later ζ divide by it; the recurrence below stops before it
    int shift = 0;
    if (largest > T(0) && isfinite(largest)) frexp(largest, &shift);
    bool lost = false;  // an entry pushed below the normal range by the largest one's shift
    for (int p = 0; p <= rows - q; ++p) {
      const T renormalised = ldexp(column[p], -shift);
      lost = lost || (column[p] != T(0) && !detail::is_normal(renormalised));
      column[p] = renormalised;
    }
    if (lost && q < rows) {
      zeta[q - 2] = std::numeric_limits<T>::quiet_NaN();
      break;
    }
    first_row[0] = first_row[1];
    first_row[1] = column[0];
    for (int p = 0; p < R; ++p) {
      before[p] = last[p];
      last[p] = column[p];
    }
  }
  if (zeta_out) *zeta_out = zeta;
  // The recurrence, level by level, stopping where Wheeler's would: level k needs
  // β_k = ζ_{2k−1} ζ_{2k} > 0 and finite, and α_k = ζ_{2k} + ζ_{2k+1} finite (a non-finite ζ
  // makes one of them fail, and the ζ after it, left 0, are never reached). A failing β_k is
  // kept in beta[k] for the realizability diagnostics, which read beta[size] as the failure:
  // where α_k alone fails, beta[k] is NaN (the level is undefined), never a passing β.
  Recurrence<T, N> r;
  r.beta[0] = m[0];
  r.alpha[0] = zeta[0];
  r.size = isfinite(zeta[0]) ? 1 : 0;
  for (int k = 1; k < n && k < N && r.size == k; ++k) {  // k < N: as above, for GCC 12
    r.beta[k] = zeta[2 * k - 2] * zeta[2 * k - 1];
    r.alpha[k] = zeta[2 * k - 1] + zeta[2 * k];
    const bool beta_passes = r.beta[k] > T(0) && isfinite(r.beta[k]);
    if (beta_passes && isfinite(r.alpha[k]))
      r.size = k + 1;
    else if (beta_passes)
      r.beta[k] = std::numeric_limits<T>::quiet_NaN();
  }
  return r;
}

// Which algorithm computes the recurrence.
enum class RecurrenceAlgorithm { wheeler, product_difference };

// The recurrence of the n = m.size()/2 nodes of 2n moments, 1 <= n <= N, computed on exactly
// scaled moments and unscaled on output (size as wheeler_unscaled()). An empty recurrence
// (size 0) for another count or for m_0 not > 0 and finite, which have none; the statuses of
// invert() and realizability() say which.
template <class T, int N>
FLUIDBED_HOST_DEVICE Recurrence<T, N> recurrence(std::span<const T> m,
                                                 RecurrenceAlgorithm algorithm = RecurrenceAlgorithm::wheeler) {
  using std::isfinite;
  if (!detail::count_within(m.size(), 2, 2 * N, detail::Parity::even) || !(m[0] > T(0)) || !isfinite(m[0])) return {};
  const detail::ScaledMoments<T, N> s = detail::scaled_moments<T, N>(m);
  Recurrence<T, N> r = algorithm == RecurrenceAlgorithm::wheeler ? wheeler_unscaled<T, N>(s.view())
                                                                 : product_difference_unscaled<T, N>(s.view());
  unscale(r, s.scaling);
  return r;
}

}  // namespace fluidbed::moments
