// The scene's meshes on the GPU: one vertex array, drawn one object at a time.
#pragma once

#include "gl/handles.h"
#include "scene/mesh.h"

namespace sl {

class GpuScene {
  public:
    GpuScene(const Scene& scene, const Camera& camera, int imageHeight);

    void bind() const { glBindVertexArray(vao_.id()); }
    // Compatibility profile only: a vertex array fed through the fixed-function client arrays
    // (glVertexPointer, glNormalPointer) from the same buffers, for the `fixed` stage.
    void bindFixedFunction();
    void drawObject(std::size_t index) const { draw(mesh_.objects[index]); }
    void drawUnitQuad() const { draw(mesh_.unitQuad); }
    const SceneMesh& mesh() const { return mesh_; }
    std::size_t triangleCount() const { return mesh_.indices.size() / 3; }

  private:
    void draw(const MeshPart& part) const;
    SceneMesh mesh_;
    VertexArray vao_;
    VertexArray fixedVao_;
    Buffer vertices_;
    Buffer indices_;
};

}  // namespace sl
