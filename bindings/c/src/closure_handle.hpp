// fluidbed — the C interface's closure handle and its error handling (internal to the library).
//
// A handle is a closure of the bindings' shared layer (bindings/common): any closure of any
// registry, whose family index is its fluidbed_family. Every exported function runs its body
// through `guarded`, which turns what the library and the shared layer throw into a status, the
// failing cell's index and the message, so that no exception crosses the interface.
#pragma once

#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>

#include "any_closure.hpp"
#include "fluidbed_c.h"

struct fluidbed_closure : fluidbed::bindings::NamedClosure {};

namespace fluidbed::c_api {

using namespace fluidbed::bindings;

static_assert(family_count == FLUIDBED_FAMILY_COUNT, "fluidbed_family lists every registry of fluidbed::Registries");

void set_error(fluidbed_error* error, fluidbed_status status, std::size_t index, std::string_view message);

// Runs body(); returns FLUIDBED_OK, or the status of what it threw, with `error` filled.
template <class Body>
fluidbed_status guarded(fluidbed_error* error, Body&& body) noexcept {
  std::size_t index = 0;
  try {
    try {
      body();
      set_error(error, FLUIDBED_OK, 0, "");
      return FLUIDBED_OK;
    } catch (const CellError& cell) {
      index = cell.index;
      std::rethrow_exception(cell.cause);
    }
  } catch (const UnknownName& e) {
    set_error(error, FLUIDBED_UNKNOWN_NAME, index, e.what());
    return FLUIDBED_UNKNOWN_NAME;
  } catch (const UnknownParameter& e) {
    set_error(error, FLUIDBED_UNKNOWN_PARAMETER, index, e.what());
    return FLUIDBED_UNKNOWN_PARAMETER;
  } catch (const InvalidArgument& e) {
    set_error(error, FLUIDBED_INVALID_ARGUMENT, index, e.what());
    return FLUIDBED_INVALID_ARGUMENT;
  } catch (const std::domain_error& e) {
    set_error(error, FLUIDBED_DOMAIN_ERROR, index, e.what());
    return FLUIDBED_DOMAIN_ERROR;
  } catch (const std::exception& e) {
    set_error(error, FLUIDBED_INTERNAL_ERROR, index, e.what());
    return FLUIDBED_INTERNAL_ERROR;
  } catch (...) {
    set_error(error, FLUIDBED_INTERNAL_ERROR, index, "fluidbed: unknown exception");
    return FLUIDBED_INTERNAL_ERROR;
  }
}

// The closure of a handle, or InvalidArgument where the handle is NULL.
inline const NamedClosure& closure_of(const fluidbed_closure* handle, std::string_view function) {
  if (handle == nullptr) throw InvalidArgument("fluidbed: " + std::string(function) + ": the closure is NULL");
  return *handle;
}

}  // namespace fluidbed::c_api
