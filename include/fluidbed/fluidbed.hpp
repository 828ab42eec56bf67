// fluidbed — umbrella header: every closure of the library.
#pragma once

#include "drag.hpp"
#include "settling.hpp"
#include "elastic.hpp"
#include "interaction.hpp"
#include "kinetic_theory.hpp"
#include "moments.hpp"
