// Stage parameters: declared once (name, kind, default, range, help) and read by the HUD,
// `--set`, `stages --json`, reports and docs alike.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace sl {

enum class ParamKind { Number, Integer, Choice };

struct ParamSpec {
    std::string name;
    ParamKind kind = ParamKind::Number;
    double defaultValue = 0;              // Number / Integer
    double min = 0, max = 1, step = 0.1;  // Number / Integer; step for +/- in the window
    std::vector<std::string> choices;     // Choice; the first is the default
    std::string help;
    bool logStep = false;  // +/- multiplies/divides by (1 + step) instead of adding

    static ParamSpec number(std::string name, double def, double min, double max, double step,
                            std::string help, bool logStep = false);
    static ParamSpec integer(std::string name, double def, double min, double max, double step,
                             std::string help, bool logStep = false);
    static ParamSpec choice(std::string name, std::vector<std::string> choices, std::string help);
    std::string defaultText() const;
    std::string rangeText() const;  // "0 to 0.05" | "rgb8, depth16, ..."
};

// Current values of a stage's parameters. Every successful change bumps `generation`, which
// passes compare to know when cached work (the shadow map) is stale.
class ParamSet {
  public:
    ParamSet() = default;
    explicit ParamSet(const std::vector<ParamSpec>& specs);

    double number(const std::string& name) const;
    int integer(const std::string& name) const { return static_cast<int>(number(name)); }
    const std::string& choice(const std::string& name) const;
    bool is(const std::string& name, const std::string& value) const {
        return choice(name) == value;
    }
    std::string text(const std::string& name) const;

    // Sets from text; returns "" or a one-line error naming what is allowed.
    std::string set(const std::string& name, const std::string& value);
    // Steps a parameter by +1/-1 (window keys); choices cycle.
    void step(const std::string& name, int direction);

    const std::vector<ParamSpec>& specs() const { return specs_; }
    const ParamSpec* find(const std::string& name) const;
    unsigned generation() const { return generation_; }

  private:
    std::vector<ParamSpec> specs_;
    std::map<std::string, double> numbers_;
    std::map<std::string, std::string> choices_;
    unsigned generation_ = 0;
};

// The closest of `candidates` to `word` by edit distance, for "did you mean" hints ("" if none is
// close).
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace sl
