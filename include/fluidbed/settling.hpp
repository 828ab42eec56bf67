// fluidbed — settling and homogeneous fluidization: Richardson–Zaki exponents, terminal
// velocities of a single sphere, the equilibrium bed expansion of any drag law, and the
// minimum fluidization velocity.
#pragma once

#include "settling/bed_expansion.hpp"
#include "settling/minimum_fluidization.hpp"
#include "settling/richardson_zaki.hpp"
#include "settling/terminal_velocity.hpp"
