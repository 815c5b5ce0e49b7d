// What the course's HTML pages share (the student's page, the class page): text made safe for
// HTML, numbers with fixed decimals, and the pages' one style sheet.
#pragma once

#include <string>

namespace sl {

// `raw` as HTML text or attribute value: valid UTF-8, markup characters escaped.
std::string esc(const std::string& raw);
// `v` with `decimals` digits after the point ("12.50").
std::string numText(double v, int decimals = 2);
// The pages' <style> element.
extern const char* const kStyle;

}  // namespace sl
