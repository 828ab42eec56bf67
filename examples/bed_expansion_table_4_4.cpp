// Homogeneous bed expansion of seed 000 (Mazzei, PhD thesis, UCL 2008), Table 4.4,
// recomputed from the 1-D equilibrium of each drag closure (seed eq. 3.28):
//
//   β_classical(ε, u/ε) · u/ε = (1 − ε)(ρ_p − ρ_f) g,
//
// beside the thesis's numbers. Exits non-zero if a column reproduces worse than its
// documented tolerance (examples/seed000_table_4_4.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "fluidbed/drag/ergun.hpp"
#include "fluidbed/drag/mazzei_lettieri.hpp"
#include "fluidbed/drag/wen_yu.hpp"
#include "fluidbed/fluidization.hpp"
#include "fluidbed/settling.hpp"
#include "fluidbed/single_particle.hpp"
#include "seed000_table_4_4.hpp"

namespace {

enum Column { richardson_zaki, mazzei_lettieri, wen_yu, ergun, columns };
constexpr const char* column_name[columns] = {"R&Z", "M&L", "W&Y", "Ergun"};

double tolerance_of(const seed000::Tolerance& t, int column) {
  switch (column) {
    case richardson_zaki:
      return t.richardson_zaki;
    case mazzei_lettieri:
      return t.mazzei_lettieri;
    case wen_yu:
      return t.wen_yu;
    default:
      return t.ergun;
  }
}

}  // namespace

int main() {
  std::printf(
      "Seed 000 Table 4.4: homogeneous expansion of three liquid-fluidized beds (water, g = 9.81 m/s²).\n"
      "  System 1: Richardson & Zaki (1954), ρ_p 2780 kg/m³, d 253 µm.\n"
      "  System 2: Wilhelm & Kwauk (1948),   ρ_p 2639 kg/m³, d 373 µm.\n"
      "  System 3: Wilhelm & Kwauk (1948),   ρ_p 2351 kg/m³, d 5.21 mm. Table 4.3 prints 521 µm, a misprint:\n"
      "            with it Dallavalle's u_t = %.4f m/s is below every listed u, so no bed could exist.\n"
      "Computed from eq. 3.28 with classical buoyancy:\n"
      "  R&Z    ε = (u/u_t)^(1/n), Dallavalle u_t, n(Re_t) of eq. 3.24 (the thesis's ε_R&Z column);\n"
      "  M&L    Mazzei–Lettieri drag, compared with the thesis's ε_R&Z, which it reproduces exactly\n"
      "         (the thesis's ε_M&L column, in brackets, is CFD output a few thousandths lower);\n"
      "  W&Y    Wen & Yu (α = 2.70, Schiller–Naumann C_D);  Ergun  Ergun (1952).\n"
      "Each column: computed, thesis, difference.\n\n",
      fluidbed::single_particle::DallavalleTerminalVelocity{}(
          seed000::table_4_3[2].fluid,
          fluidbed::Particles<double>{seed000::table_4_3[2].particles.density, seed000::system_3_printed_diameter}));

  const fluidbed::drag::ConstantExponentDrag wen_yu_law = fluidbed::drag::ConstantExponentDrag::wen_yu_1966();
  double worst[3][columns] = {};
  bool complete = true;
  std::printf("sys  u [m/s]   | %-22s | %-30s | %-22s | %-22s\n", "R&Z", "M&L (thesis CFD)", "W&Y", "Ergun");
  for (const seed000::Row& row : seed000::table_4_4) {
    const seed000::System& system = seed000::table_4_3.at(static_cast<std::size_t>(row.system - 1));
    const std::optional<double> computed[columns] = {
        fluidbed::fluidization::richardson_zaki_equilibrium_voidage(row.velocity, system.fluid, system.particles),
        fluidbed::fluidization::equilibrium_voidage(fluidbed::drag::MazzeiLettieri{}, row.velocity, system.fluid,
                                                    system.particles),
        fluidbed::fluidization::equilibrium_voidage(wen_yu_law, row.velocity, system.fluid, system.particles),
        fluidbed::fluidization::equilibrium_voidage(fluidbed::drag::Ergun{}, row.velocity, system.fluid,
                                                    system.particles),
    };
    const double thesis[columns] = {row.richardson_zaki, row.richardson_zaki, row.wen_yu, row.ergun};
    std::printf("%2d   %.2e  ", row.system, row.velocity);
    for (int c = 0; c < columns; ++c) {
      if (!computed[c]) {
        complete = false;
        std::printf("| %-22s ", "no homogeneous bed");
        continue;
      }
      const double difference = *computed[c] - thesis[c];
      double& w = worst[row.system - 1][c];
      w = std::max(w, std::abs(difference));
      if (c == mazzei_lettieri)
        std::printf("| %.4f %.3f %+.4f (%.3f) ", *computed[c], thesis[c], difference, row.mazzei_lettieri);
      else
        std::printf("| %.4f %.3f %+.4f ", *computed[c], thesis[c], difference);
    }
    std::printf("\n");
  }

  bool pass = complete;
  std::printf("\nmax |difference| per system and column (tolerance):\n");
  for (int s = 0; s < 3; ++s) {
    std::printf("  system %d:", s + 1);
    for (int c = 0; c < columns; ++c) {
      const double tolerance = tolerance_of(seed000::tolerance[static_cast<std::size_t>(s)], c);
      const bool ok = worst[s][c] <= tolerance;
      pass = pass && ok;
      std::printf("  %s %.4f (%.3f)%s", column_name[c], worst[s][c], tolerance, ok ? "" : " FAIL");
    }
    std::printf("\n");
  }
  std::printf(
      "System 1's W&Y and Ergun columns do not reproduce to 0.002 (up to 0.011 and 0.014 off, reason\n"
      "unknown, probably the thesis's CFD); every other column does.\n%s\n",
      pass ? "All columns reproduce within their tolerances." : "FAILED: a column is outside its tolerance.");
  return pass ? 0 : 1;
}
