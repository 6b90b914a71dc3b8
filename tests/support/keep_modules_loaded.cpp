// Linked into the GUI's end-to-end test programs in sanitized builds only (STYK_SANITIZE,
// tests/gui/CMakeLists.txt): dlclose does nothing, so no shared object is unloaded before the
// process ends. Qt unloads its plug-ins (platform, image formats, input contexts) at exit, and
// what they still hold then looks leaked to LeakSanitizer, reported from frames of a module that
// is gone, which no suppression can match; kept loaded, those blocks stay reachable from the
// plug-ins' own data, and what remains is named (docs/fuzzing.md "Sanitized test runs").
extern "C" int dlclose(void* handle) {
  static_cast<void>(handle);
  return 0;
}
