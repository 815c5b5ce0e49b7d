#include "gl/glsl_syntax.h"

#include <cctype>
#include <map>
#include <sstream>

namespace sl {

namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

// "S:L" or "S:?" at the start of `line`: the location, and where the indentation starts.
bool location(const std::string& line, int& source, int& number, std::size_t& after) {
    std::size_t i = 0;
    while (i < line.size() && isDigit(line[i])) ++i;
    if (i == 0 || i >= line.size() || line[i] != ':' || i > 9) return false;
    source = std::stoi(line.substr(0, i));
    std::size_t j = ++i;
    if (j < line.size() && line[j] == '?') {
        number = 0;
        after = j + 2;  // glslang writes "? " before the indentation
        return j + 1 < line.size() && line[j + 1] == ' ';
    }
    while (j < line.size() && isDigit(line[j])) ++j;
    if (j == i || j - i > 9) return false;
    number = std::stoi(line.substr(i, j - i));
    after = j;
    return true;
}

}  // namespace

SyntaxTree::SyntaxTree(const std::string& printed) {
    nodes_.emplace_back();     // the root
    std::vector<int> open{0};  // open[d]: the last node at depth d - 1 (open[0] the root)
    std::istringstream in(printed);
    std::string line;
    while (std::getline(in, line)) {
        int source = 0, number = 0;
        std::size_t at = 0;
        if (!location(line, source, number, at)) continue;
        std::size_t text = line.find_first_not_of(' ', at);
        if (text == std::string::npos) continue;
        std::size_t depth = (text - at) / 2;
        if (depth + 1 > open.size()) depth = open.size() - 1;  // never deeper than a child
        SyntaxNode n;
        n.source = source;
        n.line = number;
        n.text = line.substr(text);
        n.parent = open[depth];
        int index = static_cast<int>(nodes_.size());
        nodes_[std::size_t(n.parent)].children.push_back(index);
        nodes_.push_back(std::move(n));
        open.resize(depth + 1);
        open.push_back(index);
    }
    const std::vector<int>& first = nodes_[0].children;
    if (first.size() == 1 && nodes_[std::size_t(first[0])].text.rfind("Sequence", 0) == 0)
        top_ = first[0];
}

bool SyntaxTree::symbol(const std::string& text, std::string& name, std::string& type) {
    if (text.size() < 2 || text[0] != '\'') return false;
    std::size_t close = text.find('\'', 1);
    if (close == std::string::npos || text.compare(close + 1, 2, " (") != 0) return false;
    name = text.substr(1, close - 1);
    std::size_t end = text.rfind(')');
    type = text.substr(close + 3, end == std::string::npos || end < close + 3 ? std::string::npos
                                                                              : end - close - 3);
    if (!type.empty() && type[0] == ' ') type.erase(0, 1);
    return true;
}

std::string SyntaxTree::head(const std::string& text) {
    std::size_t at = text.find(" (");
    return at == std::string::npos ? text : text.substr(0, at);
}

bool SyntaxTree::hasWord(const std::string& type, const std::string& word) {
    std::istringstream in(type);
    std::string w;
    while (in >> w)
        if (w == word) return true;
    return false;
}

std::vector<SyntaxTree::Global> SyntaxTree::globals() const {
    std::vector<Global> out;
    std::map<std::string, std::size_t> byName;
    int linker = -1;
    for (int r : roots())
        if (node(r).text.rfind("Linker Objects", 0) == 0) linker = r;
    if (linker < 0) return out;
    for (int c : node(linker).children) {
        Global g;
        if (!symbol(node(c).text, g.name, g.type) || byName.count(g.name)) continue;
        byName[g.name] = out.size();
        out.push_back(g);
    }
    // First uses, in the printed order (source order within each function).
    for (int i = 1; i < static_cast<int>(nodes_.size()); ++i) {
        std::string name, type;
        if (!symbol(node(i).text, name, type)) continue;
        auto it = byName.find(name);
        if (it == byName.end() || node(i).parent == linker) continue;
        Global& g = out[it->second];
        if (g.firstUse < 0) g.firstUse = i;
    }
    return out;
}

}  // namespace sl
