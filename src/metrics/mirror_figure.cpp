#include "metrics/mirror_figure.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace sl {

namespace {

std::string fmt(float value) {
    if (std::fabs(value) < 1e-5f) value = 0.0f;  // float rounding, not a figure: 1.2e-07 reads as 0
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", double(value));
    return text;
}

// Inside a single-quoted gnuplot string a quote is written twice.
std::string quoted(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out;
}

std::string point(const glm::vec2& p) {
    return fmt(p.x) + " " + fmt(p.y);
}

std::string coord(const glm::vec2& p) {
    return fmt(p.x) + "," + fmt(p.y);
}

std::string pair(const glm::vec2& p) {
    return "(" + fmt(p.x) + ", " + fmt(p.y) + ")";
}

// A gnuplot data block of line segments, each "a b" as two rows and a blank line.
void block(std::ostringstream& s, const char* name,
           std::initializer_list<std::pair<glm::vec2, glm::vec2>> segments) {
    s << "$" << name << " << EOD\n";
    for (const auto& [a, b] : segments) s << point(a) << "\n" << point(b) << "\n\n";
    s << "EOD\n";
}

void label(std::ostringstream& s, const std::string& text, const glm::vec2& p, int pointType) {
    s << "set label \"" << text << "\" at " << coord(p) << " point pt " << pointType
      << " ps 1.5 offset 1,-1 font 'sans,12'\n";
}

}  // namespace

std::string describeTopView(const MirrorTopView& v) {
    if (!v.valid) return "no reflected camera: " + v.reason + "\n";
    std::ostringstream s;
    s << "seen from above (x, z): p1 " << pair(v.p1) << "  p2 " << pair(v.p2) << "  eye "
      << pair(v.eye) << "  at " << pair(v.at) << "\n"
      << "eye' " << pair(v.eyePrime) << "  at' " << pair(v.atPrime) << "\n"
      << "left' " << fmt(v.left) << "  right' " << fmt(v.right) << "  near' " << fmt(v.zNear)
      << "  far' " << fmt(v.zFar) << "\n";
    return s.str();
}

std::string mirrorFigureScript(const MirrorTopView& v, const std::string& pngPath, int width,
                               int height) {
    std::ostringstream s;
    s << "set terminal pngcairo size " << width << "," << height << " font 'sans,10'\n"
      << "set output '" << quoted(pngPath) << "'\n"
      << "set size ratio -1\nset xlabel 'x'\nset ylabel 'z'\nset yrange [*:*] reverse\n"
      << "set grid lc rgb '#dddddd'\nset key outside below\nset offsets 0.3, 0.3, 0.3, 0.3\n";
    if (v.valid)
        s << "set title \"The mirror seen from above: left' " << fmt(v.left) << ", right' "
          << fmt(v.right) << ", near' " << fmt(v.zNear) << ", far' " << fmt(v.zFar) << "\"\n";
    else
        s << "set title \"No reflected camera: " << v.reason << "\"\n";

    // not a stage id: the figure block of the mirror
    block(s, "mirror", {{v.p1, v.p2}});
    block(s, "view", {{v.eye, v.at}});
    block(s, "rays", {{v.eye, v.p1}, {v.eye, v.p2}});
    label(s, "p1", v.p1, 7);
    label(s, "p2", v.p2, 7);
    label(s, "eye", v.eye, 7);
    label(s, "at", v.at, 6);
    if (!v.valid) {
        s << "plot $mirror with lines lw 4 lc rgb 'black' title \"mirror\", \\\n"
          << "     $view with lines dt 3 lc rgb 'gray40' title \"eye -> at\", \\\n"
          << "     $rays with lines lw 2 lc rgb '#1f77b4' title \"eye -> the mirror's ends\"\n";
        return s.str();
    }
    // Behind the mirror (eye' up to p1, p2) the frustum is clipped by the near plane; beyond
    // it, it is what the reflected camera renders.
    block(s, "clipped", {{v.eyePrime, v.p1}, {v.eyePrime, v.p2}});
    block(s, "frustum", {{v.p1, v.far1}, {v.p2, v.far2}, {v.far1, v.far2}});
    block(s, "viewPrime", {{v.eyePrime, v.atPrime}});
    block(s, "reflect", {{v.eye, v.eyePrime}});
    label(s, "eye'", v.eyePrime, 5);
    label(s, "at'", v.atPrime, 4);
    s << "set arrow from " << coord(v.eye) << " to " << coord(v.at) << " lc rgb 'gray40' dt 3\n"
      << "set arrow from " << coord(v.eyePrime) << " to " << coord(v.atPrime)
      << " lw 2 lc rgb '#2ca02c'\n";
    s << "plot $mirror with lines lw 4 lc rgb 'black' title \"mirror = near plane of eye'\", \\\n"
      << "     $rays with lines lw 2 lc rgb '#1f77b4' title \"eye -> the mirror's ends\", \\\n"
      << "     $frustum with lines lw 2 lc rgb '#d62728' title \"frustum of eye' (near' to "
         "far')\", "
         "\\\n"
      << "     $clipped with lines dt 2 lc rgb '#d62728' title \"clipped: behind the mirror\", "
         "\\\n"
      << "     $view with lines dt 3 lc rgb 'gray40' title \"eye -> at\", \\\n"
      << "     $viewPrime with lines lw 2 lc rgb '#2ca02c' title \"eye' -> at' (along the "
         "normal)\", "
         "\\\n"
      << "     $reflect with lines dt 4 lc rgb 'gray60' title \"eye -> eye' (perpendicular to the "
         "mirror)\"\n";
    return s.str();
}

}  // namespace sl
