// fluidbed — one sphere in an unbounded fluid: its drag coefficient C_D(Re) (Stokes,
// Schiller–Naumann, Dallavalle) and its terminal settling velocity (Stokes, Newton,
// Dallavalle, Schiller–Naumann), with their registries DragCoefficients and
// TerminalVelocities. Depends on core/ only (Schiller–Naumann's u_t on Boost.Math).
#pragma once

#include "single_particle/drag_coefficient.hpp"
#include "single_particle/settling_system.hpp"
#include "single_particle/terminal_velocity.hpp"
#include "single_particle/terminal_velocity_closed_forms.hpp"
