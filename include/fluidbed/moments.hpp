// fluidbed — umbrella header for moment inversion (QMOM/DQMOM quadrature).
#pragma once

#include "moments/adaptive.hpp"
#include "moments/batched.hpp"
#include "moments/correction.hpp"
#include "moments/eigen_backend.hpp"
#include "moments/inversion.hpp"
#include "moments/jacobi_eigen.hpp"
#include "moments/moment_set.hpp"
#include "moments/realizability.hpp"
#include "moments/recurrence.hpp"
