// Seed 003 (Mazzei, Marchisio & Lettieri 2012, AIChE J. 58, 3054–3069, doi:10.1002/aic.13714),
// Tables 1 and 2: the volume-density-function moments M_0 … M_7 of three ballotini powders
// (ρ_p 2500 kg/m³) computed from sieve analyses with eq. 0.17 at ε = 0.400, and the two-,
// three- and four-node quadratures that Gordon's product–difference algorithm gives for them,
// as printed:
//   Table 1   powder A (lower layer; d_sv 88 µm, c.v. 0.16) and powder B (upper layer;
//             d_sv 273 µm, c.v. 0.20). Its first part (M_0 … M_3, two nodes) is also seed 000
//             Table 6.2.
//   Table 2   the mixed powder after fluidization (all layers alike).
// Plus seed 000 Table 6.3 (the thesis's version of the mixed powder, bottom layer: M_1 is
// blank in the seed), which the two-node rule of Table 2 matches better than Table 2's own
// moments do. Used by examples/seed003_tables_1_2.cpp.
#pragma once

#include <array>

namespace seed003 {

struct Rule {
  int nodes;
  std::array<double, 4> diameters;  // ξ_i [µm], printed as whole micrometres
  std::array<double, 4> weights;    // φ_i [–], printed to three decimals
};

struct Powder {
  const char* name;
  std::array<double, 8> moments;  // M_k [µm^k], printed to three significant digits (M_0 = 0.600)
  std::array<Rule, 3> rules;      // two, three and four nodes
  double sauter_diameter;         // d_sv [µm] the seed 003 text states for the sieve data; 0: none
};

// What the printed digits resolve: the true value lies within half a unit of the last digit.
inline constexpr int moment_significant_digits = 3;
inline constexpr double diameter_half_unit = 0.5;   // µm
inline constexpr double weight_half_unit = 0.0005;  // –

// The mixed powder's two-node rule is inconsistent with its own printed moments (see
// examples/seed003_tables_1_2.cpp) and is checked against seed 000 Table 6.3 below instead.
inline constexpr int mixed_powder = 2;

inline constexpr std::array<Powder, 3> tables_1_2{{
    {"Table 1, powder A",
     {0.600, 5.45e1, 5.06e3, 4.82e5, 4.67e7, 4.61e9, 4.63e11, 4.73e13},
     {{{2, {75, 103}, {0.262, 0.338}},
       {3, {61, 89, 112}, {0.069, 0.400, 0.131}},
       {4, {52, 77, 98, 119}, {0.018, 0.214, 0.318, 0.050}}}},
     88.0},
    {"Table 1, powder B",
     {0.600, 1.70e2, 4.98e4, 1.52e7, 4.80e9, 1.57e12, 5.32e14, 1.86e17},
     {{{2, {240, 355}, {0.380, 0.220}},
       {3, {208, 287, 395}, {0.143, 0.376, 0.081}},
       {4, {181, 252, 328, 413}, {0.043, 0.322, 0.194, 0.041}}}},
     273.0},
    {"Table 2, mixed powder",
     {0.600, 1.16e2, 2.82e4, 7.84e6, 2.34e9, 7.32e11, 2.37e14, 7.95e16},
     {{{2, {105, 304}, {0.332, 0.268}},
       {3, {88, 244, 360}, {0.258, 0.259, 0.083}},
       {4, {84, 174, 275, 379}, {0.226, 0.106, 0.222, 0.046}}}},
     0.0},
}};

// Seed 000 Table 6.3: M_0, M_2, M_3 (M_1 blank) and the two-node rule 105/304 µm, 0.331/0.269.
struct PartialMoments {
  int order;
  double value;
};
inline constexpr std::array<PartialMoments, 3> seed000_table_6_3_moments{{{0, 0.600}, {2, 2.85e4}, {3, 7.95e6}}};
inline constexpr Rule seed000_table_6_3_rule{2, {105, 304}, {0.331, 0.269}};

}  // namespace seed003
