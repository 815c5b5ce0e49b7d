// The stages, in lecture order (stage_list.h): what a stage file defines, and the lookups every
// floor above render/ uses. render/ never calls this: a Renderer is handed the list
// (stageInfos()) by whoever makes it.
#pragma once

#include <string>
#include <vector>

#include "gl/source_rules.h"
#include "render/stage_interface.h"
#include "stages/bench_series.h"

namespace sl {

// What a stage file defines: what the renderer needs (StageInfo) and what grading reads.
struct StageDefinition : StageInfo {
    // What the student's shaders of this stage must or must not say, read from glslang's syntax
    // tree (gl/source_rules.h): a finding is a note on the row for the instructor, not a score.
    std::vector<SourceRule> sourceRules;
    // What `bench` measures of the stage beyond its defaults (stages/bench_series.h).
    std::vector<BenchSeries> benchSeries;
};

// Every stage, in the order of stage_list.h (defined by src/stages/registry.cpp).
const std::vector<StageDefinition>& stageRegistry();
const StageDefinition* findStage(const std::string& id);
std::vector<std::string> stageIds();
// The first stage (stage_list.h): lighting alone, drawn with our shaders. Every shadow stage's
// unshadowed baseline (StageInfo::unshadowedIsOwn), bench's baseline and the default stage.
const StageDefinition& lightingStage();
// Whether `id` is a stage that needs a scene with a mirror (false for an unknown id).
bool stageNeedsMirror(const std::string& id);
// The registry as the renderer takes it (Renderer's constructor).
std::vector<const StageInfo*> stageInfos();

// One bench series with the stage that declares it.
struct StageSeries {
    const StageDefinition* stage;
    const BenchSeries* series;
};
// Every stage's series of `group`, in bench's row order (BenchSeries::rank, then stage order,
// then the order each stage declares them).
std::vector<StageSeries> benchSeriesIn(BenchGroup group);

}  // namespace sl
