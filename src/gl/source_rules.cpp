#include "gl/source_rules.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "gl/glsl_syntax.h"
#include "io/files.h"

namespace sl {

namespace {

using Sources = std::set<std::string>;

constexpr std::size_t kMaxFindings = 6;  // notes per rule and program
constexpr int kMaxRounds = 16;           // the fixed point comes in two or three
// Beyond these a program is not read (a note says so): a student's 1 MB shader must not make the
// rules, which are no score, cost the row its time budget, nor recurse the stack away.
constexpr std::size_t kMaxNodes = 100000;
constexpr int kMaxDepth = 1000;

bool startsWith(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

void add(Sources& into, const Sources& from) {
    into.insert(from.begin(), from.end());
}

// A comparison a rule looks at: relational and equality operators, equal()/notEqual() and
// step() (a comparison that returns 0 or 1).
bool isComparison(const std::string& head) {
    return startsWith(head, "Compare ") || head == "Equal" || head == "NotEqual" || head == "step";
}

// dFdx, dFdy and fwidth (glslang prints dFdx as dPdx), in their fine and coarse forms too.
bool isDerivative(const std::string& head) {
    return startsWith(head, "dPdx") || startsWith(head, "dPdy") || startsWith(head, "fwidth");
}

bool isAssignment(const std::string& head) {
    return head == "move second child to first child" ||
           head.find("second child into first child") != std::string::npos;
}

// What one comparison reads: its place and the inputs of each operand.
struct Comparison {
    int source = 0, line = 0;
    std::string op;
    Sources left, right;
};

// Which inputs every value of one stage depends on: a flow-insensitive, context-insensitive
// fixed point over the printed tree. With `control`, a value assigned or returned under a
// condition also depends on the condition's inputs.
class StageFlow {
  public:
    StageFlow(const SyntaxTree& tree, std::map<std::string, Sources> fedInputs, bool control)
        : tree_(tree), fed_(std::move(fedInputs)), control_(control) {
        for (const SyntaxTree::Global& g : tree.globals()) globals_.insert(g.name);
        for (int r : tree.roots()) collectAssigned(r, "");
        std::size_t before = 0;
        for (int round = 0; round < kMaxRounds; ++round) {
            walkAll();
            std::size_t size = 0;
            for (const auto& [key, s] : vars_) size += s.size();
            for (const auto& [key, s] : returns_) size += s.size();
            if (round > 0 && size == before) break;
            before = size;
        }
        recording_ = true;
        walkAll();
    }

    // The inputs a global output (a vertex `out`/varying) carries.
    Sources output(const std::string& name) const {
        auto it = vars_.find(name);
        return it == vars_.end() ? Sources{} : it->second;
    }
    const std::vector<Comparison>& comparisons() const { return comparisons_; }

  private:
    const SyntaxNode& at(int i) const { return tree_.node(i); }

    bool global(const std::string& name) const {
        return globals_.count(name) || startsWith(name, "gl_");
    }
    std::string key(const std::string& name, const std::string& function) const {
        return global(name) ? name : function + "/" + name;
    }

    // The variable an assignment writes: the symbol under indexing and swizzles.
    std::string target(int i, const std::string& function) const {
        while (true) {
            std::string name, type;
            if (SyntaxTree::symbol(at(i).text, name, type)) return key(name, function);
            if (at(i).children.empty()) return {};
            i = at(i).children[0];
        }
    }

    static std::string signature(const std::string& text, const char* prefix) {
        return SyntaxTree::head(text.substr(std::string(prefix).size()));
    }

    void collectAssigned(int i, std::string function, int depth = 0) {
        if (depth >= kMaxDepth) return;
        const std::string& text = at(i).text;
        if (startsWith(text, "Function Definition: "))
            function = signature(text, "Function Definition: ");
        if (isAssignment(SyntaxTree::head(text)) && !at(i).children.empty())
            assigned_.insert(target(at(i).children[0], function));
        for (int c : at(i).children) collectAssigned(c, function, depth + 1);
    }

    void walkAll() {
        comparisons_.clear();
        for (int r : tree_.roots()) {
            if (startsWith(at(r).text, "Linker Objects")) continue;
            eval(r, "", {});
        }
    }

    Sources symbolSources(const std::string& name, const std::string& function) const {
        std::string k = key(name, function);
        if (global(name) && !assigned_.count(k)) {  // an input: a uniform, attribute, built-in
            auto fed = fed_.find(name);
            return fed != fed_.end() ? fed->second : Sources{name};
        }
        auto it = vars_.find(k);
        return it == vars_.end() ? Sources{} : it->second;
    }

    // gl_FragCoord.z and .w are depth, not the pixel's place on screen: a separate input.
    bool fragDepth(int i) const {
        const SyntaxNode& n = at(i);
        std::string head = SyntaxTree::head(n.text), name, type;
        if ((head != "direct index" && head != "vector swizzle") || n.children.size() != 2 ||
            !SyntaxTree::symbol(at(n.children[0]).text, name, type) || name != "gl_FragCoord")
            return false;
        std::vector<int> indices;
        std::vector<int> stack{n.children[1]};
        while (!stack.empty()) {
            int k = stack.back();
            stack.pop_back();
            const std::string& t = at(k).text;
            if (!t.empty() && t[0] >= '0' && t[0] <= '9') indices.push_back(t[0] - '0');
            for (int c : at(k).children) stack.push_back(c);
        }
        return !indices.empty() &&
               std::all_of(indices.begin(), indices.end(), [](int c) { return c == 2 || c == 3; });
    }

    Sources eval(int i, const std::string& function, const Sources& control) {
        if (depth_ >= kMaxDepth) return {};
        struct Deeper {
            int& d;
            explicit Deeper(int& depth) : d(++depth) {}
            ~Deeper() { --d; }
        } deeper(depth_);
        const SyntaxNode& n = at(i);
        const std::string head = SyntaxTree::head(n.text);
        std::string name, type;
        if (SyntaxTree::symbol(n.text, name, type)) return symbolSources(name, function);
        if (startsWith(head, "Constant:")) return {};
        if (startsWith(n.text, "Function Definition: ")) {
            std::string f = signature(n.text, "Function Definition: ");
            for (int c : n.children) {
                if (startsWith(at(c).text, "Function Parameters:")) {
                    std::vector<std::string>& params = params_[f];
                    params.clear();
                    for (int p : at(c).children)
                        if (SyntaxTree::symbol(at(p).text, name, type)) {
                            params.push_back(f + "/" + name);
                            if (SyntaxTree::hasWord(type, "out") ||
                                SyntaxTree::hasWord(type, "inout"))
                                outParams_.insert(params.back());
                        }
                } else {
                    eval(c, f, {});
                }
            }
            return {};
        }
        if (startsWith(n.text, "Function Call: ")) {
            std::string f = signature(n.text, "Function Call: ");
            const std::vector<std::string>& params = params_[f];
            Sources result = returns_[f];
            for (std::size_t k = 0; k < n.children.size(); ++k) {
                Sources arg = eval(n.children[k], function, control);
                if (k >= params.size()) continue;
                add(vars_[params[k]], arg);
                if (outParams_.count(params[k])) {  // written back to the argument
                    std::string t = target(n.children[k], function);
                    if (!t.empty()) add(vars_[t], vars_[params[k]]);
                }
            }
            return result;
        }
        if (isAssignment(head) && n.children.size() == 2) {
            std::string t = target(n.children[0], function);
            Sources value = eval(n.children[1], function, control);
            if (control_) add(value, control);
            if (!t.empty()) add(vars_[t], value);
            return t.empty() ? value : vars_[t];
        }
        if (head == "Test condition and select" || startsWith(head, "Loop with condition")) {
            // Labels ("Condition", "true case", "Loop Body", ...) precede the part they name.
            Sources condition, inner = control, value;
            std::string label;
            for (int c : n.children) {
                const std::string& t = at(c).text;
                if (t == "Condition" || t == "Loop Condition" || t == "true case" ||
                    t == "false case" || t == "Loop Body" || t == "Loop Terminal Expression" ||
                    startsWith(t, "true case is null") || startsWith(t, "No loop")) {
                    label = t;
                    continue;
                }
                if (label == "Condition" || label == "Loop Condition") {
                    condition = eval(c, function, control);
                    add(inner, condition);
                    add(value, condition);
                } else {
                    add(value, eval(c, function, inner));
                }
            }
            return value;
        }
        if (startsWith(head, "Branch: Return with expression") && !n.children.empty()) {
            Sources value = eval(n.children[0], function, control);
            if (control_) add(value, control);
            add(returns_[function], value);
            return {};
        }
        if (fragDepth(i)) return {"gl_FragCoord.z"};
        const bool derivative = isDerivative(head);
        std::vector<Sources> operands;
        Sources all;
        for (int c : n.children) {
            operands.push_back(eval(c, function, control));
            add(all, operands.back());
            // Statements after a return (or discard, break, continue) never run: glslang keeps
            // them in the tree, a stub's `return margin;` above the old code must not count it.
            if (head == "Sequence" && startsWith(at(c).text, "Branch: ")) break;
        }
        if (recording_ && isComparison(head) && operands.size() == 2)
            comparisons_.push_back({n.source, n.line, head, operands[0], operands[1]});
        if (derivative) all.insert(kScreenDerivative);
        return all;
    }

    const SyntaxTree& tree_;
    std::map<std::string, Sources> fed_;
    bool control_;
    std::set<std::string> globals_, assigned_, outParams_;
    std::map<std::string, Sources> vars_, returns_;
    std::map<std::string, std::vector<std::string>> params_;
    bool recording_ = false;
    int depth_ = 0;
    std::vector<Comparison> comparisons_;
};

// Both stages of a program: the fragment stage's inputs carry what the vertex stage wrote.
struct ProgramFlow {
    SyntaxTree vertexTree, fragmentTree;
    StageFlow vertex, fragment;

    ProgramFlow(const StageTrees& trees, bool control)
        : vertexTree(trees.vertex),
          fragmentTree(trees.fragment),
          vertex(vertexTree, {}, control),
          fragment(fragmentTree, fedInputs(vertexTree, vertex), control) {}

    static std::map<std::string, Sources> fedInputs(const SyntaxTree& vertexTree,
                                                    const StageFlow& flow) {
        std::map<std::string, Sources> fed;
        for (const SyntaxTree::Global& g : vertexTree.globals())
            if (SyntaxTree::hasWord(g.type, "out")) fed[g.name] = flow.output(g.name);
        return fed;
    }
};

struct Located {
    const Comparison* comparison;
    const std::vector<std::string>* files;
};

std::vector<Located> comparisonsOf(const ProgramFlow& flow, const ProgramSource& program) {
    std::vector<Located> out;
    for (const Comparison& c : flow.vertex.comparisons()) out.push_back({&c, &program.vertexFiles});
    for (const Comparison& c : flow.fragment.comparisons())
        out.push_back({&c, &program.fragmentFiles});
    return out;
}

std::string fileOf(const Located& l) {
    int s = l.comparison->source;
    return s >= 0 && std::size_t(s) < l.files->size() ? (*l.files)[std::size_t(s)] : "";
}

std::string placeOf(const Located& l) {
    return printableName(fileOf(l)) + ":" + std::to_string(l.comparison->line);
}

bool studentsFile(const ProgramSource& program, const std::string& file) {
    return !file.empty() && program.students && program.students(file);
}

// The group labels whose names appear in `sources`.
std::vector<std::string> labelsIn(const Sources& sources, const std::vector<NameGroup>& groups) {
    std::vector<std::string> out;
    for (const NameGroup& g : groups)
        for (const std::string& name : g.names)
            if (sources.count(name)) {
                out.push_back(g.label + " (" + name + ")");
                break;
            }
    return out;
}

std::string listed(const std::vector<std::string>& items, const char* last) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i)
        out += (i == 0                  ? ""
                : i + 1 == items.size() ? std::string(" ") + last + " "
                                        : ", ") +
               items[i];
    return out;
}

void constantComparisons(const SourceRule& rule, const ProgramSource& program,
                         std::vector<std::string>& findings) {
    ProgramFlow flow(program.trees, false);
    std::set<std::string> watched;
    for (const NameGroup& g : rule.groups) watched.insert(g.names.begin(), g.names.end());
    auto onlyWatched = [&](const Sources& s) {
        return !s.empty() && std::all_of(s.begin(), s.end(),
                                         [&](const std::string& n) { return watched.count(n); });
    };
    std::set<std::string> said;
    std::size_t count = 0;
    for (const Located& l : comparisonsOf(flow, program)) {
        const Comparison& c = *l.comparison;
        const Sources* value = onlyWatched(c.left) && c.right.empty()   ? &c.left
                               : onlyWatched(c.right) && c.left.empty() ? &c.right
                                                                        : nullptr;
        if (!value || !studentsFile(program, fileOf(l)) || !said.insert(placeOf(l)).second)
            continue;
        if (++count > kMaxFindings) break;
        findings.push_back("possible gaming: " + placeOf(l) + " compares " +
                           listed(labelsIn(*value, rule.groups), "and") + " with a constant; " +
                           rule.why);
    }
}

void comparisonDependsOn(const SourceRule& rule, const ProgramSource& program,
                         std::vector<std::string>& findings) {
    bool students = false;
    for (const auto* files : {&program.vertexFiles, &program.fragmentFiles})
        for (const std::string& f : *files) students = students || studentsFile(program, f);
    if (!students) return;
    ProgramFlow flow(program.trees, true);
    std::optional<Located> best;  // the comparison that misses the fewest groups
    std::vector<std::string> bestMissing;
    for (const Located& l : comparisonsOf(flow, program)) {
        Sources all = l.comparison->left;
        add(all, l.comparison->right);
        if (!all.count(rule.sampler)) continue;
        std::vector<std::string> missing;
        for (const NameGroup& g : rule.groups)
            if (std::none_of(g.names.begin(), g.names.end(),
                             [&](const std::string& n) { return all.count(n); }))
                missing.push_back(g.label);
        if (missing.empty()) return;  // one comparison that depends on every group is enough
        if (!best || missing.size() < bestMissing.size()) {
            best = l;
            bestMissing = missing;
        }
    }
    std::string file =
        printableName(program.fragmentFiles.empty() ? program.pass : program.fragmentFiles[0]);
    if (!best)
        findings.push_back(file + ": no comparison reads '" + rule.sampler + "'; " + rule.why);
    else
        findings.push_back(placeOf(*best) + ": the shadow comparison does not depend on " +
                           listed(bestMissing, "or") + "; " + rule.why);
}

}  // namespace

SourceRule SourceRule::comparisonDependsOn(std::string pass, std::string sampler,
                                           std::vector<NameGroup> groups, std::string why) {
    SourceRule r;
    r.kind = Kind::ComparisonDependsOn;
    r.pass = std::move(pass);
    r.sampler = std::move(sampler);
    r.groups = std::move(groups);
    r.why = std::move(why);
    return r;
}

SourceRule SourceRule::constantComparison(std::vector<NameGroup> groups, std::string why) {
    SourceRule r;
    r.kind = Kind::ConstantComparison;
    r.groups = std::move(groups);
    r.why = std::move(why);
    return r;
}

std::vector<std::string> sourceFindings(const std::vector<SourceRule>& rules,
                                        const ProgramSource& program) {
    std::vector<std::string> findings;
    std::size_t lines = 0;
    for (const std::string* tree : {&program.trees.vertex, &program.trees.fragment})
        lines += std::size_t(std::count(tree->begin(), tree->end(), '\n'));
    if (lines > kMaxNodes) {
        if (!rules.empty())
            findings.push_back("pass " + program.pass +
                               ": source rules not read: glslang's tree of "
                               "it has " +
                               std::to_string(lines) + " nodes, more than " +
                               std::to_string(kMaxNodes));
        return findings;
    }
    for (const SourceRule& rule : rules) {
        if (!rule.pass.empty() && rule.pass != program.pass) continue;
        if (rule.kind == SourceRule::Kind::ConstantComparison)
            constantComparisons(rule, program, findings);
        else
            comparisonDependsOn(rule, program, findings);
    }
    return findings;
}

}  // namespace sl
