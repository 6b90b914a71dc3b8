// Plug-in entry of libstyk_c3d14.so: registers C3D14.
#include <memory>

#include "c3d14.hpp"
#include "styk/plugin/sdk.hpp"

namespace {

styk::plugin::ElementList make_elements() {
  styk::plugin::ElementList elements;
  elements.push_back(std::make_unique<styk::plugins::C3D14>());
  return elements;
}

}  // namespace

STYK_PLUGIN(make_elements)
