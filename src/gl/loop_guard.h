// The browser edition's loop budget (docs/web.md, "A shader that loops"): WebGL has no way to stop
// a draw, so a student's loop that never ends held the tab until Chromium lost the context. The
// ESSL translation (gl/glsl_for_webgl.cpp) counts every loop iteration of a file into one budget
// per invocation and stops the loops past it (guardLoops); a fragment shader also answers a
// probe draw (gl_es3.cpp) with where its budget ran out, and the draw throws LoopBudgetSpent
// naming the file. The desktop build compiles the GLSL itself (no budget: its workers' CPU-time
// budget stops a loop, TIMEOUT) and never throws it.
#pragma once

#include <stdexcept>
#include <string>

namespace sl {

// Iterations of all loops together in one invocation (a vertex or a fragment): our shaders run
// at most 12 (a 3x3 filter: 3 + 9), a 31x31 filter 1023 (31 + 961). What a stopped loop costs
// grows with it: every fragment of the draw runs the budget out (docs/web.md has the seconds).
constexpr int kLoopBudget = 1024;

// A draw whose fragment shader ran a loop past kLoopBudget: the student's file (as messages show
// it), e.g. "mywork/depth/lit.frag: error: a loop ran past 1024 iterations ...".
class LoopBudgetSpent : public std::runtime_error {
  public:
    explicit LoopBudgetSpent(const std::string& file);
};

// What the translation adds to a fragment shader with loops (names the GL layer looks for).
constexpr const char* kLoopProbe = "sl_loopProbe";  // uniform bool: the probe draw
constexpr const char* kLoopGuardLine = "// shadowlab loop budget: ";  // then the file's name

// `essl` (SPIRV-Cross's ESSL 3.00: one statement a line, every loop body in braces on the line
// after its `for (...)`, `while (...)` or `do`) with each loop's body opened by a step of the
// budget that breaks past it; unchanged when it has no loop. A fragment shader's main also
// answers the probe: with kLoopProbe true it discards every fragment but those whose budget ran
// out, which write 1 to the output at location 0 (one is declared when it has none; a
// non-float output there gets no probe). Throws std::runtime_error where a loop's body does
// not open as expected (never run a loop unguarded).
std::string guardLoops(const std::string& essl, bool fragment, const std::string& file);

}  // namespace sl
