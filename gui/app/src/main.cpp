// styk-gui: the desktop pre/postprocessor (docs/gui.md).
// Usage: styk-gui [MODEL.inp | RESULTS.styk.h5]
//        styk-gui --list-elements   (prints the element registry, as `styk elements`, and exits)
#include <QApplication>
#include <QSurfaceFormat>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "main_window.hpp"
#include "styk/elements/element_setup.hpp"

namespace {

// The element types the program offers and where each comes from (built-in or the plug-in's
// path): what a user checks after installing a plug-in. Needs no display.
void print_elements(const styk::ElementRegistry& registry) {
  std::printf("%-8s %5s  %-10s %s\n", "type", "nodes", "source", "description");
  for (const std::string& name : registry.names()) {
    const styk::ElementRegistry::Entry* entry = registry.entry(name);
    std::printf("%-8s %5d  %-10s %s\n", name.c_str(), entry->element->node_count(),
                entry->source.c_str(), entry->element->description().c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  styk::PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  styk::ElementRegistry registry;
  const std::vector<styk::PluginDiagnostic> problems =
      styk::setup_element_registry(registry, libraries, styk::standard_plugin_directories());
  for (const styk::PluginDiagnostic& problem : problems)
    std::fprintf(stderr, "styk-gui: warning: %s\n", problem.message.c_str());
  if (argc > 1 && std::strcmp(argv[1], "--list-elements") == 0) {
    print_elements(registry);
    return 0;
  }

  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);
  QApplication::setApplicationName("styk-gui");

  styk::gui::MainWindow window(registry);
  window.show();
  if (argc > 1) window.open_file(QString::fromLocal8Bit(argv[1]));
  window.offer_recovery();  // a session that stopped without saving left its model
  return app.exec();
}
