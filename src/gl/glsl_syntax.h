// glslang's syntax tree, read back from the text glslang prints of it (EShMsgAST). Every glslang
// since 11 prints it the same way ("S:L" location, two spaces per depth, one node a line), while
// the headers of its tree classes are not installed from glslang 14 on: the printout is the one
// view of the tree that every supported system has.
#pragma once

#include <string>
#include <vector>

namespace sl {

struct SyntaxNode {
    int source = -1;   // source-string number (-1: none printed)
    int line = 0;      // 0: glslang printed "?" (a declaration without a place)
    std::string text;  // e.g. "Compare Equal ( temp bool)", "'N' ( in 3-component vector of float)"
    int parent = -1;
    std::vector<int> children;
};

class SyntaxTree {
  public:
    // Reads the tree lines of a glslang info log (other lines are skipped).
    explicit SyntaxTree(const std::string& printed);

    const std::vector<SyntaxNode>& nodes() const { return nodes_; }
    const SyntaxNode& node(int i) const { return nodes_[std::size_t(i)]; }
    // The top-level nodes (function definitions, global initialisers, "Linker Objects"): the
    // children of the "Sequence" glslang prints first.
    const std::vector<int>& roots() const { return nodes_[std::size_t(top_)].children; }

    // A symbol node's name and type text ("'n' ( smooth in ...)" -> "n", "smooth in ...").
    static bool symbol(const std::string& text, std::string& name, std::string& type);
    // The operator or node name: the text before " (" ("Compare Equal", "Function Call: f(vf3;").
    static std::string head(const std::string& text);
    // Whether the type text has `word` as a whole word ("smooth in 3-component" has "in").
    static bool hasWord(const std::string& type, const std::string& word);

    struct Global {
        std::string name, type;
        int firstUse = -1;  // node of the first use outside "Linker Objects" (-1: never used)
    };
    // The stage's declared globals (its "Linker Objects"), each with its first use.
    std::vector<Global> globals() const;

  private:
    std::vector<SyntaxNode> nodes_;  // nodes_[0]: a root above the printed top level
    int top_ = 0;
};

}  // namespace sl
