#include "render/gpu_scene.h"

#include <cstddef>
#include <stdexcept>

#include "gl/shader_library.h"

namespace sl {

GpuScene::GpuScene(const Scene& scene, const Camera& camera, int imageHeight)
    : mesh_(tessellate(scene, camera, imageHeight)),
      vao_(VertexArray::create()),
      vertices_(Buffer::create()),
      indices_(Buffer::create()) {
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    glBufferData(GL_ARRAY_BUFFER, mesh_.vertices.size() * sizeof(Vertex), mesh_.vertices.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, mesh_.indices.size() * sizeof(std::uint32_t),
                 mesh_.indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(kNormalAttribute);
    glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, normal)));
    glBindVertexArray(0);
}

void GpuScene::bindFixedFunction() {
#ifdef SHADOWLAB_GL_ES  // no client-state arrays in ES 3.0: the fixed stage is native only
    throw std::runtime_error("the fixed-function vertex arrays need desktop OpenGL");
#else
    if (!fixedVao_) {
        fixedVao_ = VertexArray::create();
        glBindVertexArray(fixedVao_.id());
        glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(3, GL_FLOAT, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, position)));
        glEnableClientState(GL_NORMAL_ARRAY);
        glNormalPointer(GL_FLOAT, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, normal)));
    }
    glBindVertexArray(fixedVao_.id());
#endif
}

void GpuScene::draw(const MeshPart& part) const {
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(part.indexCount), GL_UNSIGNED_INT,
                   reinterpret_cast<void*>(std::size_t(part.firstIndex) * sizeof(std::uint32_t)));
}

}  // namespace sl
