// What the window does, apart from freeglut: the renderers (one per tree and scene, made on
// first use in the one context), stage and tree switching, keys, shader reload, shots, the HUD.
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <set>

#include "platform/glut_window.h"
#include "platform/shader_watch.h"
#include "render/hud.h"

namespace sl {

enum class HudMode { Full, Compact, Hidden };

class WindowSession {
  public:
    using Clock = std::chrono::steady_clock;
    // Needs the window's context current. Throws UsageError, SceneError, ShaderError.
    explicit WindowSession(const WindowArgs& args);

    // Input. Each returns true when the picture must be redrawn.
    bool key(unsigned char key, bool shift);
    bool drag(int dx, int dy);
    // The mouse wheel: `steps` notches toward the target (negative: away).
    bool zoom(int steps);
    // A few times a second: settled shader edits, the end of an on-screen message.
    bool tick(Clock::time_point now);

    // Draws the stage and the HUD into the default framebuffer. With `saveTo`, the frame is
    // also saved (without the HUD unless `withHud`); returns "" or the error.
    std::string draw(int width, int height, const std::string& saveTo = "", bool withHud = false);
    bool animating() const { return animateLight_; }
    // True after a draw that had no good program for the stage (the exit code of --frames runs).
    bool shaderFailed() const { return !renderError_.empty(); }
    // The state a test reads (--state), as JSON text.
    std::string stateJson() const;

  private:
    struct Slot {
        std::unique_ptr<Renderer> renderer;
        Camera homeCamera;
        glm::vec3 homeLight;
    };
    bool selectStage(std::size_t index, GlslTree sessionTree);
    Slot& slotFor(GlslTree tree, const std::string& scene, const std::string& stage);
    std::string sceneFor(const StageInfo& stage);
    void reload(bool force);
    // The watchdog: changed shaders are drawn in the trial worker first (see program_trial.h).
    void startTrial(bool force);
    bool finishTrial();
    void adopt(const std::vector<TrialVerdict>& verdicts);
    std::vector<TrialStage> trialStages();
    // Parameter values are tried too: a loop whose length a uniform sets would otherwise reach
    // the window's context with the first new value. Sets: a stage's non-default values.
    using Sets = std::vector<std::pair<std::string, std::string>>;
    static Sets nonDefault(const ParamSet& params);
    bool drawsStudentPrograms() const;
    bool startParamTrialIfNeeded();  // true when it started one
    void adoptParams(const std::vector<TrialVerdict>& verdicts);
    bool pending(const Sets& sets) const;  // the student's programs have not drawn with these
    bool paramsPending() const;            // ... with the values on screen
    std::vector<Sets> setsInUse() const;   // the values on screen, and the split halves'
    bool valuesPending() const;            // any of those not drawn in the worker yet
    std::string refusedKey(const std::string& stage) const;
    std::vector<std::string> shownErrors() const;
    // The picture waits for a trial: the student's folder in its first one, or a stage of a tree
    // switched to after its files changed, never drawn here yet. A placeholder is drawn.
    bool waitingForTrial() const;
    void saveShot();
    void flash(const std::string& text, bool error);
    std::vector<HudBlock> hudBlocks() const;
    // The stage's lessons in the tree it runs in, and the one chosen with `n` ("" when none).
    std::vector<const WindowLesson*> lessons() const;
    void nextLesson();
    std::string lessonLine() const;
    // The split view's two halves: the lesson on screen and the next one in the same scene
    // (its failure and its fix), or the mirror's texture and stencil methods. Empty: no pair.
    struct Half {
        std::string name;
        std::vector<std::pair<std::string, std::string>> sets;
    };
    std::vector<Half> splitHalves() const;
    void drawSplit(int width, int height);
    HudBlock flashBlock() const;
    std::string ignoredMark(const std::string& param) const;
    std::string title() const;
    std::string treeText() const;
    std::string readPixelsToPng(const std::string& path) const;
    float textScale(int width, int height) const;
    void drawStage(GLuint target, int width, int height);

    // The picture's own framebuffer when panels take bands of the window.
    class PictureTarget {
      public:
        void resize(int width, int height);
        GLuint framebuffer() const { return fbo_.id(); }

      private:
        int width_ = 0, height_ = 0;
        Renderbuffer colour_, depthStencil_;
        Framebuffer fbo_;
    };
    PictureTarget picture_;
    bool split_ = false;
    std::size_t lesson_ = 0;                           // index into lessons(); 0 = the defaults
    std::pair<std::string, std::string> lessonScene_;  // stage, scene its lesson brings
    int pictureTop_ = 0, pictureHeight_ = 0, pictureBottom_ = 0;

    WindowArgs args_;
    RenderRequest request_;
    std::string startScene_;
    GlslTree tree_;                      // the user's tree; fixed runs legacy whatever it is
    std::map<std::string, Slot> slots_;  // "tree/scene"
    Slot* slot_ = nullptr;
    std::string scene_;
    std::map<std::string, bool> sceneHasMirror_;
    Hud hud_;
    ShaderWatch watch_;
    int width_ = 0, height_ = 0;
    std::size_t selectedParam_ = 0;
    bool showHelp_ = false;
    HudMode hudMode_ = HudMode::Compact;  // the full panel is one key away (i)
    bool animateLight_ = false;
    Clock::time_point lastAnimation_;
    std::vector<std::string> reloadErrors_;
    std::shared_ptr<ProgramTrial> trial_;
    bool trialForce_ = false;
    std::uint64_t trialFingerprint_ = 0;
    std::string trialFile_;    // the file changed last when the trial began
    bool firstTrial_ = false;  // the student's folder is in its first trial: none of it drawn yet
    bool treeTrial_ = false;   // the tree switched to is in a trial (its files changed meanwhile)
    std::map<GlslTree, std::uint64_t> triedFingerprint_;  // the files each tree last drew with
    std::map<std::string, Sets> fileTrialSets_;  // stage -> the values the file trial drew with
    bool paramTrial_ = false;                    // the running trial tries values, not files
    std::vector<Sets> paramTrialTried_;          // its values, in the order tried
    std::string paramTrialKey_;                  // "tree/stage"
    // Per "tree/stage" of the student's programs now adopted: values that drew in the worker,
    // values that did not (and why), and the last good ones on screen (drawn while others wait).
    std::map<std::string, std::set<Sets>> goodSets_;
    std::map<std::string, std::map<Sets, std::string>> badSets_;
    std::map<std::string, Sets> lastGoodSets_;
    std::map<std::string, std::string> refused_;  // "tree/stage": why its new programs were refused
    std::set<std::string> drewOnce_;              // "tree/stage" drawn by a good program here
    std::string renderError_, printedRenderError_;
    std::string flash_;
    bool flashIsError_ = false;
    Clock::time_point flashUntil_;
    double drawMs_ = 0;
    long drawnFrames_ = 0;  // frames drawn (a test waits for a new one)
};

}  // namespace sl
