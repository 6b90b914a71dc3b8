// A shared library that is not a Styk plug-in: its exported function has the wrong name.
#include "styk/core/plugin_api.h"

extern "C" STYK_PLUGIN_EXPORT int styk_plugin_register_v0(const StykPluginHost*, StykPluginReply*) {
  return STYK_PLUGIN_OK;
}
