// fluidbed — homogeneous fluidization with any drag law: the equilibrium bed expansion and
// its comparison with Richardson–Zaki, the response time of an expanding bed, minimum
// fluidization (registry MinimumFluidizations), the Syamlal–O'Brien calibration from u_mf,
// and Geldart's powder groups. Depends on drag/, settling/ and
// single_particle/ (and Boost.Math).
#pragma once

#include "fluidization/bed_expansion.hpp"
#include "fluidization/geldart.hpp"
#include "fluidization/minimum_fluidization.hpp"
#include "fluidization/syamlal_obrien_calibration.hpp"
