#include "core/shared_library.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace silva {

void* shared_library_symbol(const char* file, const char* symbol) {
  // dlopen keeps one handle per library and counts references: opening again returns the same one.
  void* library = dlopen(file, RTLD_NOW | RTLD_GLOBAL);
  if (library == nullptr) {
    const char* reason = dlerror();
    throw std::runtime_error(std::string("cannot open ") + file + " (" + (reason ? reason : "unknown reason") +
                             "); scripts/install-deps.sh installs it");
  }
  void* address = dlsym(library, symbol);
  if (address == nullptr)
    throw std::runtime_error(std::string(file) + " has no " + symbol + ": not the version Silva was built against");
  return address;
}

}  // namespace silva
