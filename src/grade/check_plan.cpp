#include "grade/check_plan.h"

#include <algorithm>
#include <set>

#include "io/usage_error.h"
#include "scene/scene_json.h"
#include "stages/registry.h"
#include "stages/stage.h"

namespace sl {

namespace {

bool declares(const StageInfo& info, const std::string& param) {
    for (const ParamSpec& p : info.params)
        if (p.name == param) return true;
    return false;
}

// --all's requests (checkRequests).
std::vector<RenderRequest> allRequests(const StageCheckArgs& a, std::vector<std::string>& notes) {
    const RenderRequest& base = a.base;
    std::vector<GlslTree> trees = {GlslTree::Core, GlslTree::Legacy};
    if (a.glslGiven) {
        trees = {base.tree};
    } else if (!base.overlay.empty()) {
        trees = {GlslTree::Core};
        notes.push_back(
            "--shaders without --glsl: checking the core tree (add --glsl legacy for "
            "a GLSL 1.20 overlay)");
    }
    for (const auto& [name, value] : base.sets) {
        bool any = false;
        for (const StageInfo& s : stageRegistry()) any = any || declares(s, name);
        if (!any)
            throw UsageError("--set " + name + "=" + value + ": no stage declares '" + name + "'");
    }
    bool sceneHasMirror = true;
    if (base.sceneGiven) sceneHasMirror = loadScene(base.scene).mirror.has_value();
    std::vector<RenderRequest> out;
    for (GlslTree tree : trees)
        for (const StageInfo& s : stageRegistry()) {
            if (s.legacyOnly && tree == GlslTree::Core) continue;
            RenderRequest r = base;
            r.stage = s.id;
            r.tree = tree;
            r.sets.clear();
            for (const auto& set : base.sets)
                if (declares(s, set.first)) r.sets.push_back(set);
            if (s.needsMirror && base.sceneGiven && !sceneHasMirror) {
                r.scene = "slides";
                r.sceneGiven = false;  // the stage's own scene
                std::string note = "stage " + s.id + ": --scene " + base.scene +
                                   " has no mirror, checked in its own scene";
                if (std::find(notes.begin(), notes.end(), note) == notes.end())
                    notes.push_back(note);
            }
            out.push_back(r);
        }
    return out;
}

}  // namespace

std::vector<RenderRequest> checkRequests(const StageCheckArgs& a, std::vector<std::string>& notes) {
    if (a.all) return allRequests(a, notes);
    RenderRequest base = a.base;
    const StageInfo* info = findStage(base.stage);
    if (info && info->legacyOnly && !a.glslGiven) base.tree = GlslTree::Legacy;
    return {base};
}

GradingPlan defaultPlan(const StageCheckArgs& a, const std::vector<RenderRequest>& requests,
                        const Submission* submission) {
    const ShippedTrees& shipped = shippedTrees();
    GradingPlan plan;
    plan.name = a.all ? "every stage" : "stage " + a.base.stage;
    for (const RenderRequest& r : requests) {
        StagePlan st;
        st.stage = r.stage;
        st.tree = treeName(r.tree);
        const std::set<std::string>& tree = shipped.of(r.tree);
        st.files = expectedFiles(r.stage, tree);
        if (submission) {
            std::vector<std::string> handed = stageFiles(*submission, r.stage, tree);
            if (st.files.empty())
                st.skipped = "stage " + r.stage +
                             " has no shaders to hand in (fixed function): not graded with "
                             "--shaders";
            else if (handed.empty())
                st.missingFiles = st.files;
            else
                st.files = handed;
        }
        for (const CheckCase& c : checkCases(r, a.narrowed, a.customView, a.settings.seed)) {
            RowPlan row;
            row.check = c;
            row.points = 1;
            st.rows.push_back(row);
        }
        st.points = double(st.rows.size());
        plan.stages.push_back(std::move(st));
    }
    return plan;
}

}  // namespace sl
