#include "gl_view.hpp"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace styk::gui {

GlView::GlView(QWidget* parent) : QOpenGLWidget(parent) {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setSamples(0);  // the renderer's pixels are deterministic without multisampling
  setFormat(format);
  setMouseTracking(true);
  setMinimumSize(320, 240);
}

GlView::~GlView() {
  // GL objects belong to the context: delete them while it is current.
  makeCurrent();
  renderer_.reset();
  doneCurrent();
}

void GlView::initializeGL() {
  QOpenGLContext* context = QOpenGLContext::currentContext();
  renderer_ = std::make_unique<render::GlRenderer>([context](const char* name) {
    return reinterpret_cast<void*>(context->getProcAddress(name));
  });
}

void GlView::paintGL() {
  const qreal ratio = devicePixelRatioF();
  const int w = std::max(16, int(std::lround(width() * ratio)));
  const int h = std::max(16, int(std::lround(height() * ratio)));
  renderer_->draw(scene_.frame(w, h, view_));
  ++frames_;
}

void GlView::set_named_view(const QString& name) {
  const bool perspective = view_.spec.perspective;
  view_ = ViewState{};
  view_.spec.name = name.toStdString();
  view_.spec.perspective = perspective;
  update();
}

void GlView::set_perspective(bool on) {
  view_.spec.perspective = on;
  update();
}

void GlView::fit() {
  view_.spec.zoom = 1.0;
  view_.pan_right = view_.pan_up = 0.0;
  update();
}

QImage GlView::grab_picture() { return grabFramebuffer(); }

void GlView::mousePressEvent(QMouseEvent* event) { last_ = event->position().toPoint(); }

void GlView::mouseMoveEvent(QMouseEvent* event) {
  const QPoint p = event->position().toPoint();
  const QPoint d = p - last_;
  last_ = p;
  const bool pan = (event->buttons() & Qt::MiddleButton) ||
                   ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
  if (pan) {
    const double per_pixel = 1.0 / (std::max(1, height()) * view_.spec.zoom);
    view_.pan_right += d.x() * per_pixel;
    view_.pan_up -= d.y() * per_pixel;
    update();
  } else if (event->buttons() & Qt::LeftButton) {
    // Half a turn across the widget's width; elevation stays within +-89 degrees.
    view_.spec.azimuth -= 180.0 * d.x() / std::max(1, width());
    view_.spec.elevation = std::clamp(view_.spec.elevation + 180.0 * d.y() / std::max(1, height()),
                                      -89.0, 89.0);
    update();
  } else if (event->buttons() == Qt::NoButton && !scene_.empty()) {
    const qreal ratio = devicePixelRatioF();
    const auto hit = scene_.probe(int(p.x() * ratio), int(p.y() * ratio), int(8 * ratio));
    if (!hit) {
      emit probed(QString());
      return;
    }
    QString text = QString("node %1 (%2, %3, %4)")
                       .arg(hit->node_id)
                       .arg(hit->position[0], 0, 'g', 6)
                       .arg(hit->position[1], 0, 'g', 6)
                       .arg(hit->position[2], 0, 'g', 6);
    if (hit->value)
      text += QString("  %1 = %2").arg(QString::fromStdString(hit->field)).arg(*hit->value, 0, 'E', 4);
    emit probed(text);
  }
}

void GlView::mouseDoubleClickEvent(QMouseEvent*) { fit(); }

void GlView::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  view_.spec.zoom = std::clamp(view_.spec.zoom * std::pow(1.15, steps), 0.05, 200.0);
  update();
}

}  // namespace styk::gui
