#pragma once
/// @file Functions of a shared library opened at first need (dlopen), so that a program starts without
/// loading that library and everything it depends on.

namespace silva {

/// The address of `symbol` in the shared library `file`, opening the library on the first call that names
/// it; throws std::runtime_error naming the library, the symbol and the loader's reason when either is missing.
void* shared_library_symbol(const char* file, const char* symbol);

/// shared_library_symbol as a function of type Fn (the caller states the type the symbol has).
template <class Fn>
Fn* shared_library_function(const char* file, const char* symbol) {
  return reinterpret_cast<Fn*>(shared_library_symbol(file, symbol));
}

}  // namespace silva
