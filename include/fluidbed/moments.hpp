// fluidbed — umbrella header for moment inversion (QMOM/DQMOM quadrature).
//
// It includes batched.hpp, dqmom_batched.hpp and eigen_backend.hpp, the headers that need Eigen 3.4. A host
// without Eigen includes the per-cell headers it uses instead (inversion.hpp, adaptive.hpp,
// realizability.hpp, correction.hpp, moment_set.hpp, dqmom.hpp, ...), which need only the standard
// library and Boost.Math (moment_set.hpp's constants).
#pragma once

#include "moments/accuracy.hpp"
#include "moments/adaptive.hpp"
#include "moments/batched.hpp"
#include "moments/correction.hpp"
#include "moments/dqmom.hpp"
#include "moments/dqmom_batched.hpp"
#include "moments/eigen_backend.hpp"
#include "moments/inversion.hpp"
#include "moments/jacobi_eigen.hpp"
#include "moments/moment_set.hpp"
#include "moments/realizability.hpp"
#include "moments/recurrence.hpp"
