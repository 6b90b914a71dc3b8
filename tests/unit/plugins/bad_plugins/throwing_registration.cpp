// A plug-in whose factory throws: the SDK turns it into STYK_PLUGIN_FAILED with the text.
#include <stdexcept>

#include "styk/plugin/sdk.hpp"

namespace {

styk::plugin::ElementList make_elements() {
  throw std::runtime_error("cannot read the element table tmpl.dat");
}

}  // namespace

STYK_PLUGIN(make_elements)
