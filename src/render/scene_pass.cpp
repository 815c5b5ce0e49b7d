#include "render/scene_pass.h"

#include "math/camera.h"
#include "scene/mesh.h"

namespace sl {

Viewer cameraViewer(const FrameContext& f) {
    return {viewMatrix(f.camera), projectionMatrix(f.camera, float(f.width) / float(f.height)),
            f.camera.eye};
}

void drawSceneLit(Program& program, const FrameContext& f, const Viewer& viewer, int debugView,
                  const PerObject& perObject) {
    program.use();
    program.set("view", viewer.view);
    program.set("projection", viewer.projection);
    program.set("eyePosition", viewer.eye);
    program.set("lightPosition", f.lightPosition);
    program.set("ambient", f.scene.material.ambient);
    program.set("diffuse", f.scene.material.diffuse);
    program.set("specular", f.scene.material.specular);
    program.set("shininess", f.scene.material.shininess);
    program.set("debugView", debugView);
    program.checkSamplerUnits();  // the stage set its units before calling
    f.gpu.bind();
    for (std::size_t i = 0; i < f.scene.objects.size(); ++i) {
        const Object& o = f.scene.objects[i];
        glm::mat4 model = modelMatrix(o);
        program.set("model", model);
        program.set("normalMatrix", glm::mat3(glm::transpose(glm::inverse(model))));
        program.set("objectColor", o.color);
        if (perObject) perObject(program, i, model);
        f.gpu.drawObject(i);
    }
    glBindVertexArray(0);
}

void drawSceneFromLight(Program& program, const FrameContext& f,
                        const glm::mat4& lightViewProjection, FromLight which,
                        const PerObject& perObject) {
    program.use();
    program.set("lightViewProjection", lightViewProjection);
    f.gpu.bind();
    for (std::size_t i = 0; i < f.scene.objects.size(); ++i) {
        const Object& o = f.scene.objects[i];
        if (which == FromLight::None || (which == FromLight::Casters && !o.castsShadow) ||
            (which == FromLight::Receivers && o.castsShadow))
            continue;
        glm::mat4 model = modelMatrix(o);
        program.set("model", model);
        if (perObject) perObject(program, i, model);
        f.gpu.drawObject(i);
    }
    glBindVertexArray(0);
}

void clearToBackground(const FrameContext& f) {
    glClearColor(f.scene.background.r, f.scene.background.g, f.scene.background.b, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace sl
