// fluidbed — umbrella header: every closure of the library.
#pragma once

#include "single_particle.hpp"
#include "settling.hpp"
#include "drag.hpp"
#include "fluidization.hpp"
#include "elastic.hpp"
#include "interaction.hpp"
#include "kinetic_theory.hpp"
#include "moments.hpp"
#include "polydisperse.hpp"
