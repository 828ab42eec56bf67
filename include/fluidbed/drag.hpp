// fluidbed — the drag family: every monodisperse law with run-time selection (AnyDragLaw,
// DragLaws), and the polydisperse Beetstra law for species of a mixture.
#pragma once

#include "drag/any_drag_law.hpp"
#include "drag/beetstra_polydisperse.hpp"
