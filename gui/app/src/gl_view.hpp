// The 3D view: a QOpenGLWidget drawing the session's Scene through render::GlRenderer (GL 3.3
// core functions loaded via QOpenGLContext::getProcAddress into the renderer's own glad table).
// Mouse (docs/gui.md): left drag orbits, middle drag or Shift+left drag pans, the wheel zooms,
// hovering probes the node under the cursor, double-click fits; a left click picks (Shift adds,
// Ctrl removes), a right drag picks everything visible in a box. Also plays and exports the
// results animation (session/animation.hpp).
#pragma once

#include <QOpenGLWidget>
#include <QPoint>
#include <QTimer>
#include <memory>

#include "session/animation.hpp"
#include "session/scene.hpp"
#include "styk/render/gl_renderer.hpp"

class QRubberBand;

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

  // Picking: what a click picks, and the selection (kept in the scene, drawn as markers).
  void set_pick_kind(PickKind kind);
  PickKind pick_kind() const { return scene_.selection().kind(); }
  void clear_selection();
  // A click at widget position `p` (logical pixels) with the modifiers' meaning (docs/gui.md).
  void pick_at(const QPoint& p, Qt::KeyboardModifiers modifiers);
  void pick_box(const QRect& box, Qt::KeyboardModifiers modifiers);

  // Plays the animation in a loop (`interval_ms` per frame) until stop_animation().
  void play_animation(std::unique_ptr<SceneAnimation> animation, int interval_ms);
  void stop_animation();
  bool animating() const { return animation_ != nullptr; }
  // Draws every frame of `animation` (without the selection markers) and writes
  // DIR/STEM_0000.png ... and DIR/STEM.apng.
  // Returns the PNG files written; throws std::runtime_error when a file cannot be written.
  QStringList export_animation(SceneAnimation& animation, const QString& directory,
                               const QString& stem, int delay_ms);

 signals:
  void probed(const QString& text);  // empty when the cursor is over no node
  void selection_changed();
  void animation_frame(const QString& label);

 protected:
  void initializeGL() override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  void probe_at(const QPoint& p);
  void next_animation_frame();

  Scene scene_;
  ViewState view_;
  std::unique_ptr<render::GlRenderer> renderer_;
  long uploaded_revision_ = -1;  // the scene geometry in renderer_'s GL buffers (-1: none yet)
  QPoint last_;
  QPoint press_;
  bool dragged_ = false;
  QRubberBand* band_ = nullptr;
  std::unique_ptr<SceneAnimation> animation_;
  int animation_frame_ = 0;
  QTimer animation_timer_;
  long frames_ = 0;
};

}  // namespace styk::gui
