#include "render/stage_params.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace sl {

namespace {
std::string formatNumber(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}
}  // namespace

ParamSpec ParamSpec::number(std::string name, double def, double min, double max, double step,
                            std::string help, bool logStep) {
    ParamSpec p;
    p.name = std::move(name);
    p.kind = ParamKind::Number;
    p.defaultValue = def;
    p.min = min;
    p.max = max;
    p.step = step;
    p.help = std::move(help);
    p.logStep = logStep;
    return p;
}

ParamSpec ParamSpec::integer(std::string name, double def, double min, double max, double step,
                             std::string help, bool logStep) {
    ParamSpec p = number(std::move(name), def, min, max, step, std::move(help), logStep);
    p.kind = ParamKind::Integer;
    return p;
}

ParamSpec ParamSpec::choice(std::string name, std::vector<std::string> choices, std::string help) {
    ParamSpec p;
    p.name = std::move(name);
    p.kind = ParamKind::Choice;
    p.choices = std::move(choices);
    p.help = std::move(help);
    return p;
}

std::string ParamSpec::defaultText() const {
    return kind == ParamKind::Choice ? choices.front() : formatNumber(defaultValue);
}

std::string ParamSpec::rangeText() const {
    if (kind != ParamKind::Choice) return formatNumber(min) + " to " + formatNumber(max);
    std::string s;
    for (const auto& c : choices) s += (s.empty() ? "" : ", ") + c;
    return s;
}

ParamSet::ParamSet(const std::vector<ParamSpec>& specs) : specs_(specs) {
    for (const auto& p : specs_) {
        if (p.kind == ParamKind::Choice)
            choices_[p.name] = p.choices.front();
        else
            numbers_[p.name] = p.defaultValue;
    }
}

const ParamSpec* ParamSet::find(const std::string& name) const {
    for (const auto& p : specs_)
        if (p.name == name) return &p;
    return nullptr;
}

double ParamSet::number(const std::string& name) const {
    auto it = numbers_.find(name);
    if (it == numbers_.end()) throw std::logic_error("no numeric parameter '" + name + "'");
    return it->second;
}

const std::string& ParamSet::choice(const std::string& name) const {
    auto it = choices_.find(name);
    if (it == choices_.end()) throw std::logic_error("no choice parameter '" + name + "'");
    return it->second;
}

std::string ParamSet::text(const std::string& name) const {
    const ParamSpec* p = find(name);
    if (!p) return "";
    return p->kind == ParamKind::Choice ? choice(name) : formatNumber(number(name));
}

std::string ParamSet::set(const std::string& name, const std::string& value) {
    const ParamSpec* p = find(name);
    if (!p) {
        std::vector<std::string> names;
        for (const auto& s : specs_) names.push_back(s.name);
        std::string hint = closestMatch(name, names);
        std::string all;
        for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
        return "unknown parameter '" + name + "'" +
               (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
               "; this stage has: " + (all.empty() ? "none" : all);
    }
    if (p->kind == ParamKind::Choice) {
        if (std::find(p->choices.begin(), p->choices.end(), value) == p->choices.end())
            return "parameter '" + name + "' must be one of: " + p->rangeText() + " (got '" +
                   value + "')";
        if (choices_[name] != value) ++generation_;
        choices_[name] = value;
        return "";
    }
    char* end = nullptr;
    double v = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(v))
        return "parameter '" + name + "' needs a finite number (got '" + value + "')";
    if (p->kind == ParamKind::Integer && v != std::floor(v))
        return "parameter '" + name + "' needs a whole number (got '" + value + "')";
    if (v < p->min || v > p->max)
        return "parameter '" + name + "' must be in " + p->rangeText() + " (got " + value + ")";
    if (numbers_[name] != v) ++generation_;
    numbers_[name] = v;
    return "";
}

void ParamSet::step(const std::string& name, int direction) {
    const ParamSpec* p = find(name);
    if (!p) return;
    if (p->kind == ParamKind::Choice) {
        auto it = std::find(p->choices.begin(), p->choices.end(), choices_[name]);
        int n = static_cast<int>(p->choices.size());
        int i = (static_cast<int>(it - p->choices.begin()) + direction % n + n) % n;
        choices_[name] = p->choices[i];
    } else {
        double v = numbers_[name];
        if (p->logStep)
            v = direction > 0 ? std::max(v * (1 + p->step), p->min + p->step) : v / (1 + p->step);
        else
            v += direction * p->step;
        if (p->kind == ParamKind::Integer) v = std::round(v);
        numbers_[name] = std::clamp(v, p->min, p->max);
    }
    ++generation_;
}

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t bestDistance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const auto& c : candidates) {
        std::vector<std::size_t> row(c.size() + 1);
        for (std::size_t j = 0; j <= c.size(); ++j) row[j] = j;
        for (std::size_t i = 1; i <= word.size(); ++i) {
            std::size_t diagonal = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= c.size(); ++j) {
                std::size_t up = row[j];
                row[j] =
                    std::min({row[j] + 1, row[j - 1] + 1, diagonal + (word[i - 1] != c[j - 1])});
                diagonal = up;
            }
        }
        if (row[c.size()] < bestDistance) {
            bestDistance = row[c.size()];
            best = c;
        }
    }
    return best;
}

}  // namespace sl
