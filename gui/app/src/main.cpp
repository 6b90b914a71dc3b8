// styk-gui: the desktop pre/postprocessor (docs/gui.md). Usage: styk-gui [MODEL.inp | RESULTS.styk.h5]
#include <QApplication>
#include <QSurfaceFormat>

#include "main_window.hpp"
#include "session/element_setup.hpp"

int main(int argc, char** argv) {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);
  QApplication::setApplicationName("styk-gui");

  styk::PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  styk::ElementRegistry registry;
  const std::vector<std::string> warnings =
      styk::gui::load_elements(registry, libraries, STYK_PLUGIN_BUILD_DIR);
  styk::gui::MainWindow window(registry);
  for (const std::string& w : warnings) qWarning("styk-gui: %s", w.c_str());
  window.show();
  if (argc > 1) window.open_file(QString::fromLocal8Bit(argv[1]));
  return app.exec();
}
