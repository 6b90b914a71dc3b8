// The 3D view: a QOpenGLWidget drawing the session's Scene through render::GlRenderer (GL 3.3
// core functions loaded via QOpenGLContext::getProcAddress into the renderer's own glad table).
// Mouse (docs/gui.md): left drag orbits, middle drag or Shift+left drag pans, the wheel zooms,
// hovering probes the node under the cursor, double-click fits.
#pragma once

#include <QOpenGLWidget>
#include <QPoint>
#include <memory>

#include "session/scene.hpp"
#include "styk/render/gl_renderer.hpp"

namespace styk::gui {

class GlView : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit GlView(QWidget* parent = nullptr);
  ~GlView() override;

  Scene& scene() { return scene_; }
  ViewState& view() { return view_; }
  // Named view ("iso", "+x", ...): resets orbit, pan and zoom, keeps the projection.
  void set_named_view(const QString& name);
  void set_perspective(bool on);
  void fit();
  // The picture as drawn (framebuffer pixels), e.g. for File > Export PNG.
  QImage grab_picture();
  // Frames drawn since construction (for the FPS benchmark).
  long frames_drawn() const { return frames_; }

 signals:
  void probed(const QString& text);  // empty when the cursor is over no node

 protected:
  void initializeGL() override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  Scene scene_;
  ViewState view_;
  std::unique_ptr<render::GlRenderer> renderer_;
  QPoint last_;
  long frames_ = 0;
};

}  // namespace styk::gui
