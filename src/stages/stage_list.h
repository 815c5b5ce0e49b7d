// The stages in lecture order. Adding a stage: a file src/stages/<id>.cpp defining
// `StageDefinition <id>Stage()` (stages/registry.h), its shaders in both trees, and one line here.
SL_STAGE(phong)
SL_STAGE(rgb)
SL_STAGE(depth)
SL_STAGE(bias)
SL_STAGE(margin)
SL_STAGE(hardware)
SL_STAGE(fixed)
SL_STAGE(mirror)
SL_STAGE(peers)
