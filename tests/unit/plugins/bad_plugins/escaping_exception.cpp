// A hand-written entry (no SDK) that lets a C++ exception escape: the loader must catch it.
#include <stdexcept>

#include "styk/core/plugin_api.h"

extern "C" STYK_PLUGIN_EXPORT int styk_plugin_register(const StykPluginHost*, StykPluginReply*) {
  throw std::logic_error("hand-written entry gave up");
}
