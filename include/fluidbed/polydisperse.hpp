// fluidbed — the multi-fluid (DQMOM) model of a polydisperse suspension: the per-class closures
// (gas–particle and solid–solid drag of every class, polydisperse/class_closures.hpp) and Niemi's
// solids-mixture DQMOM (the per-class force balance and the volume-fraction consistency
// correction, polydisperse/mixture_dqmom.hpp). The DQMOM source terms are moments/dqmom.hpp's.
#pragma once

#include "polydisperse/class_closures.hpp"
#include "polydisperse/mixture_dqmom.hpp"
