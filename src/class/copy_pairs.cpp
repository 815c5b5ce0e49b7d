#include "class/copy_pairs.h"

#include <algorithm>

namespace sl {

std::size_t writtenTokens(const std::vector<std::string>& tokens,
                          const std::vector<std::string>& starter) {
    std::map<std::string, std::size_t> given;
    for (const std::string& t : starter) ++given[t];
    std::size_t written = 0;
    for (const std::string& t : tokens) {
        auto it = given.find(t);
        if (it != given.end() && it->second > 0)
            --it->second;
        else
            ++written;
    }
    return written;
}

std::vector<CopyPair> copyPairs(const std::vector<HandInFiles>& handIns,
                                const std::map<std::string, std::string>& starters) {
    std::map<std::string, std::vector<std::string>> starterTokens;
    for (const auto& [file, text] : starters) starterTokens[file] = normalizedTokens(text);
    // Each hand-in's written tokens, and per file the hand-ins grouped by their tokens.
    std::map<std::string, std::size_t> written;
    std::map<std::string, std::map<std::vector<std::string>, std::vector<std::string>>> groups;
    std::map<std::pair<std::string, std::vector<std::string>>, std::size_t> writtenOf;
    for (const HandInFiles& h : handIns)
        for (const auto& [file, text] : h.files) {
            std::vector<std::string> tokens = normalizedTokens(text);
            const std::vector<std::string>& starter = starterTokens[file];
            if (tokens.empty() || tokens == starter) continue;
            // A file changed only by reordering the starter still counts: at least one token.
            const std::size_t w = std::max<std::size_t>(1, writtenTokens(tokens, starter));
            written[h.name] += w;
            writtenOf[{file, tokens}] = w;
            groups[file][tokens].push_back(h.name);
        }
    std::map<std::pair<std::string, std::string>, CopyPair> pairs;
    for (const auto& [file, byTokens] : groups)
        for (const auto& [tokens, members] : byTokens)
            for (std::size_t i = 0; i < members.size(); ++i)
                for (std::size_t j = i + 1; j < members.size(); ++j) {
                    const auto& [a, b] = std::minmax(members[i], members[j]);
                    CopyPair& p = pairs[{a, b}];
                    p.a = a;
                    p.b = b;
                    p.files.push_back(file);
                    p.commonTokens += writtenOf[{file, tokens}];
                }
    std::vector<CopyPair> out;
    for (auto& [names, p] : pairs) {
        p.share = double(p.commonTokens) / double(std::max(written[p.a], written[p.b]));
        out.push_back(std::move(p));
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const CopyPair& x, const CopyPair& y) { return x.share > y.share; });
    return out;
}

}  // namespace sl
