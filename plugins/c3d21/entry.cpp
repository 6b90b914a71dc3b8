// Plug-in entry of libstyk_c3d21.so: registers C3D21.
#include <memory>

#include "c3d21.hpp"
#include "styk/plugin/sdk.hpp"

namespace {

styk::plugin::ElementList make_elements() {
  styk::plugin::ElementList elements;
  elements.push_back(std::make_unique<styk::plugins::C3D21>());
  return elements;
}

}  // namespace

STYK_PLUGIN(make_elements)
