// fluidbed — settling suspensions: the Richardson–Zaki law u_s = u_t ε^n, its exponent
// correlations (registry RichardsonZakiExponents) and the relation Re = Re_t ε^n(Re_t) solved
// for Re_t (shared with the Mazzei–Lettieri drag). The single particle's terminal velocity is
// in single_particle.hpp, the bed expansion of a drag law in fluidization.hpp.
#pragma once

#include "settling/richardson_zaki.hpp"
