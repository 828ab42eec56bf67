// fluidbed — the C interface's closure handle and its error handling (internal to the library).
//
// A handle holds a closure of any registry of fluidbed::Registries as a variant of the
// registries' variants: its index is the closure's fluidbed_family. Every exported function runs
// its body through `guarded`, which turns the library's exceptions into a status, the failing
// cell's index and the message, so that none crosses the interface.
#pragma once

#include <cstddef>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>

#include "fluidbed/registries.hpp"
#include "fluidbed_c.h"

namespace fluidbed::c_api {

template <class List>
struct ClosuresOf;
template <class... Registry>
struct ClosuresOf<RegistryList<Registry...>> {
  using Variant = std::variant<typename Registry::Variant...>;
  using Registries = std::tuple<Registry...>;
};

using AnyClosure = ClosuresOf<fluidbed::Registries>::Variant;
using RegistryTuple = ClosuresOf<fluidbed::Registries>::Registries;
inline constexpr std::size_t family_count = std::variant_size_v<AnyClosure>;
static_assert(family_count == FLUIDBED_FAMILY_COUNT, "fluidbed_family lists every registry of fluidbed::Registries");

template <std::size_t family>
using RegistryOf = std::tuple_element_t<family, RegistryTuple>;

// Calls f(law) with the closure's own type.
template <class F>
decltype(auto) visit_closure(const AnyClosure& closure, F&& f) {
  return std::visit([&](const auto& family) -> decltype(auto) { return std::visit(f, family); }, closure);
}
template <class F>
decltype(auto) visit_closure(AnyClosure& closure, F&& f) {
  return std::visit([&](auto& family) -> decltype(auto) { return std::visit(f, family); }, closure);
}

// An evaluation stopped at a cell: the cell and the library's exception, rethrown by `guarded`.
struct CellError {
  std::size_t index;
  std::exception_ptr cause;
};

// A function's failure that is not the library's (a NULL array, a closure of another family).
struct InvalidArgument : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
struct UnknownName : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
struct UnknownParameter : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

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

// cell(i) for i in [0, n); an exception of cell i becomes a CellError at i.
template <class Cell>
void for_each_cell(std::size_t n, Cell&& cell) {
  for (std::size_t i = 0; i < n; ++i) {
    try {
      cell(i);
    } catch (...) {
      throw CellError{i, std::current_exception()};
    }
  }
}

// Throws InvalidArgument unless every required array is there.
template <class... Pointer>
void require_arrays(std::size_t n, std::string_view function, const Pointer*... arrays) {
  if (n > 0 && ((arrays == nullptr) || ...))
    throw InvalidArgument("fluidbed: " + std::string(function) + ": an input or required output array is NULL");
}

}  // namespace fluidbed::c_api

struct fluidbed_closure {
  fluidbed::c_api::AnyClosure closure;
  std::string name;  // the closure's name() is a view, not necessarily terminated
  std::string reference;
};

namespace fluidbed::c_api {

// The closure of family `family` in a handle, or InvalidArgument naming what was expected.
template <std::size_t family>
const typename RegistryOf<family>::Variant& closure_of(const fluidbed_closure* handle, std::string_view function) {
  if (handle == nullptr) throw InvalidArgument("fluidbed: " + std::string(function) + ": the closure is NULL");
  if (handle->closure.index() != family)
    throw InvalidArgument("fluidbed: " + std::string(function) + ": " + handle->name + " is not a " +
                          std::string(RegistryOf<family>::family::what));
  return std::get<family>(handle->closure);
}

}  // namespace fluidbed::c_api
