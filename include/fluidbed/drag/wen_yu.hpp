// fluidbed — the constant-exponent (Lewis / Wen–Yu / Kmiec) family of drag laws.
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "../single_particle/drag_coefficient.hpp"
#include "drag_law.hpp"

namespace fluidbed::drag {

// Single-particle drag times a voidage function with a constant exponent
// (seed 000 §3.4.4.2, eq. 3.34):
//
//   β_classical = ¾ C_D(Re) ρ_f w (1 − ε) / d · ε^(−α),   Re = ρ_f ε w d / μ_f,
//
// with C_D the Schiller–Naumann coefficient (seed 000 eq. 3.35; the thesis's Table 4.4
// Wen–Yu column is reproduced only with it). Native convention: classical.
// In the viscous limit homogeneous expansion follows Richardson–Zaki with n = α + 2
// (eq. 3.39), in the inertial limit n = α/2 + 1 (eq. 3.43).
//
// Presets (seed 000 §3.4.4.2):
//   lewis()      α = 2.65   Lewis, Gilliland & Bauer (1949) Ind. Eng. Chem. 41, 1104
//   wen_yu_1966()     α = 2.70   Wen & Yu (1966) Chem. Eng. Prog. Symp. Ser. 62, 100
//   kmiec()      α = 2.78   Kmiec (1982) Chem. Eng. J. 23, 133
//   wen_yu_gidaspow() α = 2.65   what OpenFOAM, MFiX and Fluent call "WenYu": Gidaspow (1994)
//                     writes β = ¾ C_D ε φ ρ_f w ε^-2.65 / d in the pressure-gradient
//                     convention, which is ε^-2.65 in the classical one, i.e. the Lewis
//                     exponent, not Wen and Yu's own 2.70. Same numbers as lewis(),
//                     own name so that a CFD user finds the law their code calls WenYu.
// Validity: derived for ε ≳ 0.8 (dilute); used at all ε, over-expands beds in the
// intermediate regime (seed 000 Fig. 3.2). Re: the Schiller–Naumann range, Re < 1000
// and the constant 0.44 above.
class ConstantExponentDrag : public DragLaw<ConstantExponentDrag> {
 public:
  static constexpr Buoyancy native_buoyancy = Buoyancy::classical;

  // name and reference: C strings that outlive the law (literals), not std::string_views, so that
  // the laws can be made in device code (core/domain.hpp, Argument, says why).
  constexpr ConstantExponentDrag(double exponent, const char* name, const char* reference)
      : exponent_(exponent), name_(name), reference_(reference) {}

  static constexpr ConstantExponentDrag lewis() {
    return {2.65, "Lewis",
            "Lewis, W.K., Gilliland, E.R., Bauer, W.C. (1949) Ind. Eng. Chem. 41, 1104-1117, "
            "doi:10.1021/ie50474a004"};
  }
  static constexpr ConstantExponentDrag wen_yu_1966() {
    return {2.70, "WenYu1966", "Wen, C.Y., Yu, Y.H. (1966) Chem. Eng. Prog. Symp. Ser. 62(62), 100-111"};
  }
  static constexpr ConstantExponentDrag kmiec() {
    return {2.78, "Kmiec", "Kmiec, A. (1982) Chem. Eng. J. 23, 133-136, doi:10.1016/0300-9467(82)80003-8"};
  }
  static constexpr ConstantExponentDrag wen_yu_gidaspow() {
    return {2.65, "WenYuGidaspow",
            "Gidaspow, D. (1994) Multiphase Flow and Fluidization, Academic Press (the CFD codes' \"WenYu\")"};
  }

  // The presets, for the family's registry.
  static constexpr std::array<ConstantExponentDrag, 4> registered() {
    return {lewis(), wen_yu_1966(), kmiec(), wen_yu_gidaspow()};
  }

  constexpr double exponent() const { return exponent_; }
  // The exponent may be any finite number (ε^−n is finite for every finite n and ε in (0, 1]).
  template <class T>
  FLUIDBED_HOST_DEVICE constexpr Arguments<T, 1> parameter_domain() const {
    return {{{"exponent", T(exponent_), domains::finite<T>()}}};
  }
  static constexpr auto parameters() { return std::array{parameter<&ConstantExponentDrag::exponent_>("exponent")}; }
  constexpr std::string_view name() const { return name_; }
  constexpr std::string_view reference() const { return reference_; }
  constexpr ValidityRange validity() const { return {0.8, 1.0, 0.0, 1.0e5}; }

  template <class S, class T>
  FLUIDBED_HOST_DEVICE S native_beta(const S& voidage, const S& slip, const Fluid<T>& fluid,
                                     const T& diameter) const {
    using std::pow;
    const S re = particle_reynolds(fluid, diameter, voidage, slip);
    return single_particle::unhindered_beta(single_particle::SchillerNaumannCoefficient::cd_times_re(re), voidage,
                                            fluid.viscosity, diameter) *
           pow(voidage, T(-exponent_));
  }

 private:
  double exponent_;
  const char* name_;
  const char* reference_;
};

}  // namespace fluidbed::drag
