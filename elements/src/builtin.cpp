#include "styk/elements/builtin.hpp"

#include <memory>

#include "styk/elements/c3d20.hpp"
#include "styk/elements/c3d8.hpp"

namespace styk {

void register_builtin_elements(ElementRegistry& registry) {
  const std::string source = "built-in";
  registry.add(std::make_unique<C3D8>(), source);
  registry.add(std::make_unique<C3D20>(), source);
}

}  // namespace styk
