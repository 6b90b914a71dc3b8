// The GUI tests' way to read a dialog check: the InputError message a call refuses with, or
// "(accepted)" when it goes through.
#pragma once

#include <functional>
#include <string>

#include "styk/core/diagnostics.hpp"

namespace styk::gui::test {

inline std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.message();
  }
  return "(accepted)";
}

}  // namespace styk::gui::test
