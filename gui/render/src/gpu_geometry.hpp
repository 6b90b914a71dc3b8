// Private: the GL copy of a FrameGeometry. Each primitive list (faces with their index buffer,
// mesh edges, feature lines, undeformed outline, node points, line elements, integration points)
// has its own vertex array object and buffers, made once; upload() replaces their contents, draw()
// only binds and draws. This is what lets the desktop view orbit without sending the model to the
// GL again.
#pragma once

#include <array>

#include "gl_objects.hpp"
#include "styk/render/geometry.hpp"

namespace styk::render {

enum class Primitives { Faces, Edges, Features, Outline, Points, Bars, IpPoints };

class GpuGeometry {
 public:
  // Makes the (empty) buffers and vertex arrays: the context must be current.
  explicit GpuGeometry(const GladGLContext& gl);

  // Copies every primitive list of `geometry` into the GL buffers (the previous contents go).
  void upload(const FrameGeometry& geometry);
  // Draws one list as triangles, lines (bars too: the program in use widens them) or points with
  // the program in use. Nothing when empty.
  void draw(Primitives which) const;
  bool empty(Primitives which) const { return lists_[index(which)].count == 0; }
  // See FrameGeometry::closed: back faces may be culled.
  bool closed() const { return closed_; }

 private:
  struct List {
    GlVertexArray vertex_array;
    GlBuffer vertices;
    GlBuffer indices;   // faces only
    GLsizei count = 0;  // indices (faces) or vertices drawn
  };
  static std::size_t index(Primitives which) { return static_cast<std::size_t>(which); }

  const GladGLContext& gl_;
  std::array<List, 7> lists_;
  bool closed_ = false;
};

}  // namespace styk::render
