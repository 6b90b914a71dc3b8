#include "gpu_geometry.hpp"

#include <cstddef>
#include <vector>

namespace styk::render {
namespace {

// Binds the Vertex layout of the buffer bound to GL_ARRAY_BUFFER to attributes 0..3 of the
// vertex array bound now (the binding is stored in the vertex array object).
void bind_vertex_layout(const GladGLContext& gl) {
  const GLsizei stride = sizeof(Vertex);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<void*>(offsetof(Vertex, position)));
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<void*>(offsetof(Vertex, normal)));
  gl.VertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<void*>(offsetof(Vertex, color)));
  gl.VertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<void*>(offsetof(Vertex, t)));
  for (GLuint a = 0; a < 4; ++a) gl.EnableVertexAttribArray(a);
}

template <class T>
void fill(const GladGLContext& gl, GLenum target, const std::vector<T>& data) {
  // Static: written once per change of the geometry, drawn many times.
  gl.BufferData(target, static_cast<GLsizeiptr>(data.size() * sizeof(T)),
                data.empty() ? nullptr : data.data(), GL_STATIC_DRAW);
}

}  // namespace

GpuGeometry::GpuGeometry(const GladGLContext& gl) : gl_(gl) {
  for (std::size_t k = 0; k < lists_.size(); ++k) {
    List& list = lists_[k];
    list.vertex_array = make_vertex_array(gl);
    list.vertices = make_buffer(gl);
    gl.BindVertexArray(list.vertex_array.get());
    gl.BindBuffer(GL_ARRAY_BUFFER, list.vertices.get());
    bind_vertex_layout(gl);
    if (k == index(Primitives::Faces)) {
      list.indices = make_buffer(gl);
      gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, list.indices.get());  // recorded in the VAO
    }
  }
  gl.BindVertexArray(0);
}

void GpuGeometry::upload(const FrameGeometry& g) {
  gl_.BindVertexArray(0);  // leave every vertex array's element buffer binding alone
  const auto put = [&](Primitives which, const std::vector<Vertex>& vertices) {
    List& list = lists_[index(which)];
    gl_.BindBuffer(GL_ARRAY_BUFFER, list.vertices.get());
    fill(gl_, GL_ARRAY_BUFFER, vertices);
    list.count = static_cast<GLsizei>(vertices.size());
  };
  put(Primitives::Faces, g.face_vertices);
  put(Primitives::Edges, g.edges);
  put(Primitives::Features, g.features);
  put(Primitives::Outline, g.outline);
  put(Primitives::Points, g.points);
  put(Primitives::Bars, g.bars);
  put(Primitives::IpPoints, g.ip_points);
  List& faces = lists_[index(Primitives::Faces)];
  gl_.BindVertexArray(faces.vertex_array.get());
  fill(gl_, GL_ELEMENT_ARRAY_BUFFER, g.triangles);
  gl_.BindVertexArray(0);
  faces.count = static_cast<GLsizei>(g.triangles.size());
  closed_ = g.closed;
}

void GpuGeometry::draw(Primitives which) const {
  const List& list = lists_[index(which)];
  if (list.count == 0) return;
  gl_.BindVertexArray(list.vertex_array.get());
  switch (which) {
    case Primitives::Faces:
      gl_.DrawElements(GL_TRIANGLES, list.count, GL_UNSIGNED_INT, nullptr);
      break;
    case Primitives::Points:
    case Primitives::IpPoints:
      gl_.DrawArrays(GL_POINTS, 0, list.count);
      break;
    default:
      gl_.DrawArrays(GL_LINES, 0, list.count);
      break;
  }
}

}  // namespace styk::render
