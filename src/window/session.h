// The window as an application, apart from the OS window: the renderers (one per tree and
// scene, made on first use in the one context), stage and tree switching, keys, lessons and the
// split view, the watchdog's trials, shots, the HUD. Split by concern: session.cpp (renderers,
// stages, trials), session_keys.cpp, session_lessons.cpp, session_draw.cpp, hud_content.cpp,
// session_state.cpp.
#pragma once

#include <chrono>
#include <future>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "io/image.h"
#include "platform/glut_window.h"
#include "render/hud.h"
#include "window/top_view_layout.h"
#include "window/watchdog.h"
#include "window/window_args.h"

namespace sl {

enum class HudMode { Full, Compact, Hidden };

class WindowSession {
  public:
    using Clock = std::chrono::steady_clock;
    // Needs the window's context current. Throws UsageError, SceneError, ShaderError.
    explicit WindowSession(const WindowArgs& args);
    ~WindowSession();

    // The window's size before it draws at it (trials are drawn at it: a loop's cost grows
    // with the pixels).
    void resized(int width, int height) {
        width_ = width;
        height_ = height;
    }

    // Input. Each returns true when the picture must be redrawn.
    bool key(unsigned char key, bool shift);
    bool special(SpecialKey key, bool shift);
    bool drag(int dx, int dy);
    bool zoom(int steps);  // the mouse wheel: `steps` notches toward the target
    // A few times a second: settled shader edits, trials, the end of an on-screen message.
    bool tick(Clock::time_point now);
    // Scripted runs (--frames): returns once nothing waits for a trial (every trial ends).
    void settleTrials();

    // Draws the stage and the HUD into the default framebuffer. With `saveTo`, the frame is
    // also saved (without the HUD unless `withHud`); returns "" or the error.
    std::string draw(int width, int height, const std::string& saveTo = "", bool withHud = false);
    bool animating() const { return animateLight_; }
    double drawMs() const { return drawMs_; }  // the last frame's
    // True after a draw that had no good program for the stage (the exit code of --frames runs).
    bool shaderFailed() const { return !renderError_.empty(); }
    // The state a test reads (--state).
    nlohmann::json state() const;
    // Waits for the shots still being written.
    void finishShots();

  private:
    struct Slot {
        std::unique_ptr<Renderer> renderer;
        Camera homeCamera;
        glm::vec3 homeLight;
    };
    // A rectangle of the window, in GL's pixels (y up from the bottom).
    struct Rect {
        int x = 0, y = 0, width = 0, height = 0;
    };
    // session.cpp
    Renderer& renderer() const { return *slot_->renderer; }
    GlslTree shownTree() const { return renderer().shaders().tree(); }
    bool selectStage(std::size_t index, GlslTree sessionTree);
    Slot& slotFor(GlslTree tree, const std::string& scene, const std::string& stage);
    std::string sceneFor(const StageInfo& stage);
    Watchdog::OnScreen onScreen() const;
    TrialJob jobFor(GlslTree tree, const std::string& stage);
    void adopt(GlslTree tree, const std::set<std::string>& folders, bool force);
    void rebuildShown();
    std::vector<std::string> shownErrors() const;  // the on-screen stage's first
    void flash(const std::string& text, bool error);
    void complain(const std::string& text);                   // on the HUD and one line on stderr
    std::string refusalText(const Watchdog::Event& e) const;  // values refused: one HUD line
    std::string filesGone() const;  // the student files this batch stopped drawing from
    bool handleTrialEvents();       // true when something changed
    static bool offers(const StageInfo& stage, ViewMode view);
    std::string stageScene(const StageInfo& stage);  // its scene, whatever the lesson

    // session_keys.cpp
    void scroll(int pages);

    // session_state.cpp
    void saveShot();
    void shotSaid(const std::string& path, const std::string& error);
    Image readPixels() const;

    // session_lessons.cpp
    // The stage's lessons in the tree on screen, and the one `n` chose last.
    LessonChoice lessons() const;
    // The lesson whose settings (values, scene, view) are those on screen: -1 if none.
    int matchingLesson() const;
    void nextLesson();
    std::string lessonLine() const;
    // "lesson 2/4 of margin" for values that are a lesson's, else "margin (the values)".
    std::string valuesName(const Sets& sets) const;
    // The split view's two halves: the lesson on screen and the next one in the same scene
    // (its failure and its fix), or the mirror's texture and stencil methods. Empty: no pair.
    std::vector<SplitHalf> splitHalves() const;
    const WindowLesson* topViewLesson() const;  // the lesson on screen, if it brings a top view

    // session_draw.cpp
    HudRoom hudRoom() const;
    // The window rows the top and the bottom panels keep, whatever they show now (section
    // "A picture that holds still" in session_draw.cpp).
    std::pair<int, int> reservedBands(int width, int height) const;
    void layOut(int width, int height);
    Image pictureAlone(int width, int height);  // the picture at the window's size, no HUD
    void drawPicture(const Rect& area);
    void drawSplit(const Rect& area);
    // Draws the stage with `sets` into `area`, or a page saying why it cannot: what it showed
    // ("stage", "trying", "none").
    std::string drawStageIn(const Rect& area, const Sets& sets, bool onScreen);
    void noteRenderError(const std::string& why);
    void drawPage(const Rect& area, const std::vector<HudLine>& lines, const glm::vec4& background,
                  int* scroll);
    void drawTopView(const Rect& area, const WindowLesson& lesson);
    void blit(GLuint from, const Rect& to);
    float textScale(int width, int height) const;

    // hud_content.cpp
    std::vector<HudBlock> hudBlocks() const;
    std::vector<HudLine> helpLines() const;
    std::vector<HudLine> errorLines(bool all) const;
    std::string title() const;
    // The compact HUD's first line with these values on screen and parameter `selected`.
    std::string compactTitle(const ParamSet& values, std::size_t selected) const;
    std::string treeText() const;
    std::string ignoredMark(const std::string& param) const;
    std::string folderText() const;
    std::string valuesLine() const;  // "" or what the values on screen wait for
    std::vector<HudLine> tryingLines() const;
    std::string refusalLine() const;  // "" or the last refusal of values on screen
    std::vector<HudLine> errorPage(const std::string& why) const;
    static const char* const kTryingLine;
    static constexpr auto kFlashTime = std::chrono::seconds(4);

    // The picture's own framebuffer when it is not the whole window.
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

    WindowArgs args_;
    RenderRequest request_;
    std::string startScene_;
    GlslTree tree_;                      // the user's tree; fixed runs legacy whatever it is
    std::map<std::string, Slot> slots_;  // "tree/scene"
    Slot* slot_ = nullptr;
    std::string scene_, stageScene_;  // the scene shown; the stage's own, whatever the lesson
    std::map<std::string, bool> sceneHasMirror_;
    Hud hud_;
    ShaderLibrary hudShaders_;  // ours: a student's hud/text never draws the window's text
    std::unique_ptr<Watchdog> watchdog_;
    int width_ = 0, height_ = 0;
    std::size_t selectedParam_ = 0;
    bool showHelp_ = false;
    HudMode hudMode_ = HudMode::Compact;  // the full panel is one key away (i)
    int hudScroll_ = 0, pageScroll_ = 0;  // PgUp/PgDn: the full panel's lines, a page's
    bool animateLight_ = false;
    Clock::time_point lastAnimation_;
    bool split_ = false;
    std::size_t lesson_ = 0;                           // index into lessons()
    std::pair<std::string, std::string> lessonScene_;  // stage, scene its lesson brings
    // Laid out by the last draw: the panels' bands, the picture's area and the halves'.
    std::vector<HudPanel> panels_;
    std::pair<int, int> bands_{0, 0};
    Rect pictureArea_;
    std::vector<Rect> halfAreas_;
    std::vector<std::string> halvesShow_;
    std::vector<TopViewLayout::Label> topViewLabels_;  // the top view's labels, in topViewArea_
    Rect topViewArea_;
    Sets drawnWith_;                      // the values the picture on screen last drew with
    std::string pictureShows_ = "stage";  // "stage" | "trying" | "none" | "help"
    std::vector<std::string> hudText_;    // the lines the last draw's panels showed (--state)
    std::vector<std::string> pageText_;   // ... and its pages in the picture's place
    int panelLines_ = 1, pageLines_ = 1;  // what PgUp/PgDn move by: a page of the full panel's
                                          // lines, of a page's in the picture's place
    std::set<std::string> drawnHere_;     // "tree/scene/stage" a renderer here built and drew
    struct Deferred {  // programs adopted while a slot was not on screen: rebuilt when it is
        std::set<std::string> folders;
        bool force = false;
    };
    std::map<std::string, Deferred> deferred_;  // by slots_' key

    std::vector<std::string> reloadErrors_;  // the window's own rebuild of adopted programs
    std::string renderError_, printedRenderError_;
    std::set<std::string> saidErrors_;  // one stderr line per message
    std::set<std::string> adoptedBatch_;
    // The student's files each adopted stage on screen drew from before this batch: a file gone
    // since is said ("ours draws in its place"), not just "reloaded".
    std::map<std::string, std::vector<std::string>> overlayBeforeBatch_;
    bool errorsWhenBatchBegan_ = false, errorsBefore_ = false;
    bool forceNextAdopt_ = false;  // `r`: rebuild even what did not change
    // The last values refused in the worker, said on the HUD while the values they were put
    // back to stay on screen: the stage, the values put back, and the line.
    struct Refusal {
        std::string stage, line;
        GlslTree tree = GlslTree::Core;
        Sets backTo;
    };
    Refusal refusal_;
    std::string flash_;
    bool flashIsError_ = false;
    Clock::time_point flashUntil_;
    double drawMs_ = 0, idleDrawMs_ = 0;
    long drawnFrames_ = 0;  // frames drawn (a test waits for a new one)
    std::vector<std::future<std::string>> shotsWriting_;
    std::vector<std::string> shotsPaths_;
};

}  // namespace sl
