// fluidbed — the fluid–particle interaction forces other than drag and the elastic force:
// buoyancy in its three definitions, local fluid acceleration, virtual mass, lift, Faxen
// (seed 000 §3.3).
#pragma once

#include "interaction/buoyancy.hpp"
#include "interaction/virtual_mass_lift_faxen.hpp"
