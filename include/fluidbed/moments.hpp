// fluidbed — umbrella header for moment inversion (QMOM/DQMOM quadrature).
#pragma once

#include "moments/inversion.hpp"
#include "moments/jacobi_eigen.hpp"
#include "moments/realizability.hpp"
#include "moments/recurrence.hpp"
