// Plug-in entry of libstyk_c3d28.so: registers C3D28.
#include <memory>

#include "c3d28.hpp"
#include "styk/plugin/sdk.hpp"

namespace {

styk::plugin::ElementList make_elements() {
  styk::plugin::ElementList elements;
  elements.push_back(std::make_unique<styk::plugins::C3D28>());
  return elements;
}

}  // namespace

STYK_PLUGIN(make_elements)
