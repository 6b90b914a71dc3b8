#include "gl_view.hpp"

#include <QDir>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QRubberBand>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "session/apng.hpp"
#include "session/picking.hpp"
#include "session/selection_info.hpp"

namespace styk::gui {
namespace {

constexpr int kClickSlop = 3;  // pixels a click may move and still be a click, not a drag

SelectOp select_op(Qt::KeyboardModifiers modifiers) {
  if (modifiers & Qt::ControlModifier) return SelectOp::Remove;
  if (modifiers & Qt::ShiftModifier) return SelectOp::Add;
  return SelectOp::Replace;
}

render::Image to_image(const QImage& picture) {
  const QImage rgba = picture.convertToFormat(QImage::Format_RGBA8888);
  render::Image image(rgba.width(), rgba.height());
  for (int y = 0; y < rgba.height(); ++y)
    std::copy_n(rgba.constScanLine(y), std::size_t(rgba.width()) * 4,
                image.rgba.data() + std::size_t(y) * rgba.width() * 4);
  return image;
}

}  // namespace

GlView::GlView(QWidget* parent) : QOpenGLWidget(parent) {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setSamples(0);  // the renderer multisamples the model itself (FrameView::samples)
  setFormat(format);
  setMouseTracking(true);
  setMinimumSize(320, 240);
  connect(&animation_timer_, &QTimer::timeout, this, &GlView::next_animation_frame);
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
  uploaded_revision_ = -1;  // a new context holds no geometry yet
}

void GlView::paintGL() {
  const qreal ratio = devicePixelRatioF();
  const int w = std::max(16, int(std::lround(width() * ratio)));
  const int h = std::max(16, int(std::lround(height() * ratio)));
  const render::Frame& frame = scene_.frame(w, h, view_);
  // The vertex arrays go to the GL only when the scene rebuilt them; orbit, pan, zoom and
  // overlay changes draw the retained buffers.
  if (scene_.geometry_revision() != uploaded_revision_) {
    renderer_->set_geometry(frame.geometry);
    uploaded_revision_ = scene_.geometry_revision();
  }
  renderer_->draw_view(frame);
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

void GlView::set_pick_kind(PickKind kind) {
  Selection selection = scene_.selection();
  selection.set_kind(kind);
  scene_.set_selection(selection);
  update();
  emit selection_changed();
}

void GlView::clear_selection() {
  scene_.set_selection(Selection(pick_kind()));
  update();
  emit selection_changed();
}

void GlView::pick_at(const QPoint& p, Qt::KeyboardModifiers modifiers) {
  if (scene_.empty() || scene_.unrolled()) return;
  const qreal ratio = devicePixelRatioF();
  scene_.frame(std::max(16, int(std::lround(width() * ratio))),
               std::max(16, int(std::lround(height() * ratio))), view_);
  const Picker picker(scene_);
  const auto hit =
      picker.pick(int(p.x() * ratio), int(p.y() * ratio), pick_kind(), int(std::lround(8 * ratio)));
  Selection selection = scene_.selection();
  const SelectOp op = select_op(modifiers);
  if (!hit && op == SelectOp::Replace) selection.clear();  // a click on empty space
  if (hit) selection.apply(op, {*hit});
  scene_.set_selection(selection);
  update();
  emit selection_changed();
}

void GlView::pick_box(const QRect& box, Qt::KeyboardModifiers modifiers) {
  if (scene_.empty() || scene_.unrolled()) return;
  const qreal ratio = devicePixelRatioF();
  scene_.frame(std::max(16, int(std::lround(width() * ratio))),
               std::max(16, int(std::lround(height() * ratio))), view_);
  const Picker picker(scene_);
  const QRect r = box.normalized();
  Selection selection = scene_.selection();
  selection.apply(select_op(modifiers),
                  picker.pick_box(int(r.left() * ratio), int(r.top() * ratio),
                                  int(r.right() * ratio), int(r.bottom() * ratio), pick_kind()));
  scene_.set_selection(selection);
  update();
  emit selection_changed();
}

void GlView::mousePressEvent(QMouseEvent* event) {
  last_ = press_ = event->position().toPoint();
  dragged_ = false;
  if (event->button() == Qt::RightButton) {
    if (!band_) band_ = new QRubberBand(QRubberBand::Rectangle, this);
    band_->setGeometry(QRect(press_, QSize()));
    band_->show();
  }
}

void GlView::mouseReleaseEvent(QMouseEvent* event) {
  const QPoint p = event->position().toPoint();
  if (event->button() == Qt::RightButton && band_) {
    band_->hide();
    if (dragged_) pick_box(QRect(press_, p), event->modifiers());
  } else if (event->button() == Qt::LeftButton && !dragged_) {
    pick_at(p, event->modifiers());
  }
}

void GlView::mouseMoveEvent(QMouseEvent* event) {
  const QPoint p = event->position().toPoint();
  const QPoint d = p - last_;
  last_ = p;
  if (event->buttons() != Qt::NoButton && (p - press_).manhattanLength() > kClickSlop)
    dragged_ = true;
  if (!dragged_ && event->buttons() != Qt::NoButton) return;  // may still become a click
  const bool pan =
      (event->buttons() & Qt::MiddleButton) ||
      ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
  if (event->buttons() & Qt::RightButton) {
    if (band_) band_->setGeometry(QRect(press_, p).normalized());
  } else if (pan) {
    const double per_pixel = 1.0 / (std::max(1, height()) * view_.spec.zoom);
    view_.pan_right += d.x() * per_pixel;
    view_.pan_up -= d.y() * per_pixel;
    update();
  } else if ((event->buttons() & Qt::LeftButton) && !scene_.unrolled()) {
    // Half a turn across the widget's width; elevation stays within +-89 degrees. (The unrolled
    // map is flat: it pans and zooms but does not turn.)
    view_.spec.azimuth -= 180.0 * d.x() / std::max(1, width());
    view_.spec.elevation =
        std::clamp(view_.spec.elevation + 180.0 * d.y() / std::max(1, height()), -89.0, 89.0);
    update();
  } else if (event->buttons() == Qt::NoButton && !scene_.empty()) {
    probe_at(p);
  }
}

void GlView::probe_at(const QPoint& p) {
  if (scene_.unrolled()) return;  // the map's points are not the model's
  const qreal ratio = devicePixelRatioF();
  // Integration-point values shown: the element under the cursor reports its points' values.
  if (scene_.point_field()) {
    const Picker picker(scene_);
    const auto face = picker.face_at(int(p.x() * ratio), int(p.y() * ratio));
    const auto probe = face ? scene_.element_probe(face->element) : std::nullopt;
    emit probed(probe ? QString::fromStdString(element_probe_summary(*probe)) : QString());
    return;
  }
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
    text +=
        QString("  %1 = %2").arg(QString::fromStdString(hit->field)).arg(*hit->value, 0, 'E', 4);
  emit probed(text);
}

void GlView::mouseDoubleClickEvent(QMouseEvent*) { fit(); }

void GlView::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  view_.spec.zoom = std::clamp(view_.spec.zoom * std::pow(1.15, steps), 0.05, 200.0);
  update();
}

void GlView::play_animation(std::unique_ptr<SceneAnimation> animation, int interval_ms) {
  animation_ = std::move(animation);
  animation_frame_ = 0;
  next_animation_frame();
  animation_timer_.start(std::max(10, interval_ms));
}

void GlView::stop_animation() {
  animation_timer_.stop();
  animation_.reset();
}

void GlView::next_animation_frame() {
  if (!animation_) return;
  animation_->show(scene_, animation_frame_);
  emit animation_frame(QString::fromStdString(animation_->frame_label(animation_frame_)));
  animation_frame_ = (animation_frame_ + 1) % animation_->frame_count();
  update();
}

QStringList GlView::export_animation(SceneAnimation& animation, const QString& directory,
                                     const QString& stem, int delay_ms) {
  if (!QDir().mkpath(directory))
    throw std::runtime_error("cannot create " + directory.toStdString());
  QStringList files;
  std::vector<render::Image> frames;
  // The pictures show the results only: no selection markers.
  const Selection selection = scene_.selection();
  scene_.set_selection(Selection(selection.kind()));
  struct Restore {
    Scene& scene;
    const Selection& selection;
    ~Restore() { scene.set_selection(selection); }
  } restore{scene_, selection};
  for (int k = 0; k < animation.frame_count(); ++k) {
    animation.show(scene_, k);
    const QImage picture = grabFramebuffer();
    const QString path = QString::fromStdString(
        animation_frame_path(directory.toStdString(), stem.toStdString(), k));
    if (picture.isNull() || !picture.save(path, "PNG"))
      throw std::runtime_error("cannot write " + path.toStdString());
    files << path;
    frames.push_back(to_image(picture));
  }
  write_apng((directory + "/" + stem + ".apng").toStdString(), frames, delay_ms);
  update();
  return files;
}

}  // namespace styk::gui
