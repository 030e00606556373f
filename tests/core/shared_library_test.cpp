// Functions of a shared library opened at first need: known answers from libm, and the errors for a missing
// library or symbol.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "core/shared_library.hpp"

namespace silva {
namespace {

TEST(SharedLibrary, ResolvesAFunctionThatComputesTheKnownAnswer) {
  auto* const cosine = shared_library_function<double(double)>("libm.so.6", "cos");
  EXPECT_EQ(cosine(0.0), 1.0);
  EXPECT_EQ(shared_library_symbol("libm.so.6", "cos"), reinterpret_cast<void*>(cosine));  // opened again: the same one
}

TEST(SharedLibrary, MissingLibraryNamesItAndTheInstaller) {
  try {
    shared_library_symbol("libsilva-no-such-library.so.1", "f");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cannot open libsilva-no-such-library.so.1"), std::string::npos) << message;
    EXPECT_NE(message.find("scripts/install-deps.sh"), std::string::npos) << message;
  }
}

TEST(SharedLibrary, MissingSymbolNamesLibraryAndSymbol) {
  try {
    shared_library_symbol("libm.so.6", "silva_no_such_symbol");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("libm.so.6 has no silva_no_such_symbol"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace silva
