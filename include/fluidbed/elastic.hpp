// fluidbed — elastic force, the other interaction forces, and the stability of homogeneous
// fluidization (seed 000 §3.3, §3.5, §4.6).
#pragma once

#include "elastic/elastic_modulus.hpp"
#include "elastic/interaction_forces.hpp"
#include "elastic/stability.hpp"
