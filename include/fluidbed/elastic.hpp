// fluidbed — the elastic moduli and force, and the stability of homogeneous fluidization
// (seed 000 §3.5, §4.6). The other interaction forces are in interaction.hpp.
#pragma once

#include "elastic/elastic_modulus.hpp"
#include "elastic/stability.hpp"
