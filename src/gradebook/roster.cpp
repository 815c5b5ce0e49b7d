#include "gradebook/roster.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "gradebook/csv.h"
#include "io/files.h"
#include "io/usage_error.h"

namespace sl {

namespace {

constexpr std::size_t kMaxRosterRows = 100000;  // students

std::string trimmed(const std::string& s) {
    std::size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::string lowered(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

}  // namespace

const RosterEntry* Roster::find(const std::string& name) const {
    for (const RosterEntry& e : entries)
        if (e.handIn == name) return &e;
    const std::string shown = escapedName(name);  // a name that is not UTF-8, as outputs show it
    if (shown != name)
        for (const RosterEntry& e : entries)
            if (e.handIn == shown) return &e;
    return nullptr;
}

Roster parseRoster(const std::string& input, const std::string& origin) {
    auto fail = [&](int line, const std::string& what) { csvFail(origin, line, what); };
    std::vector<CsvRecord> records = parseCsv(input, origin, kMaxRosterRows + 1, "students");
    if (records.empty())
        fail(1, "empty: give a header row id,name,email,hand-in and a student per row");
    static const std::vector<std::vector<std::string>> kHeader = {
        {"id", "student id", "student_id"},
        {"name"},
        {"email", "e-mail"},
        {"hand-in", "hand_in", "handin", "hand-in name", "hand_in_name", "submission"}};
    const CsvRecord& head = records.front();
    bool headerOk = head.fields.size() == kHeader.size();
    for (std::size_t c = 0; headerOk && c < kHeader.size(); ++c) {
        const auto& names = kHeader[c];
        headerOk =
            std::find(names.begin(), names.end(), lowered(trimmed(head.fields[c]))) != names.end();
    }
    if (!headerOk) fail(head.line, "the header must be id,name,email,hand-in");
    Roster roster;
    std::map<std::string, int> handIns, ids;
    for (std::size_t k = 1; k < records.size(); ++k) {
        const CsvRecord& r = records[k];
        if (r.fields.size() != kHeader.size())
            fail(r.line, std::to_string(r.fields.size()) +
                             " fields, expected 4 (id,name,email,"
                             "hand-in; a field holding a comma is quoted)");
        RosterEntry e;
        e.who.id = trimmed(r.fields[0]);
        e.who.name = trimmed(r.fields[1]);
        e.who.email = trimmed(r.fields[2]);
        e.handIn = trimmed(r.fields[3]);
        e.line = r.line;
        if (e.who.id.empty()) fail(r.line, "no id");
        if (e.handIn.empty()) fail(r.line, "no hand-in name");
        if (!handIns.emplace(e.handIn, r.line).second)
            fail(r.line, "hand-in '" + printableName(e.handIn) + "' is already on line " +
                             std::to_string(handIns[e.handIn]));
        if (!ids.emplace(e.who.id, r.line).second)
            fail(r.line, "id '" + printableName(e.who.id) + "' is already on line " +
                             std::to_string(ids[e.who.id]));
        roster.entries.push_back(std::move(e));
    }
    return roster;
}

Roster loadRoster(const std::string& path) {
    std::string text;
    std::string err = readRegularFile(path, kCsvMaxBytes, text);
    if (!err.empty()) throw UsageError("--roster: " + printableName(path) + ": " + err);
    return parseRoster(text, path);
}

bool attachRoster(const Roster& roster, const std::string& handIn, StudentRecord& r) {
    std::optional<RosterInfo> who;
    if (const RosterEntry* e = roster.find(handIn)) who = e->who;
    if (who == r.roster) return false;
    r.roster = who;
    return true;
}

std::vector<std::string> handInsNotOnRoster(const Roster& roster,
                                            const std::vector<std::string>& names) {
    std::vector<std::string> out;
    for (const std::string& n : names)
        if (!roster.find(n)) out.push_back(n);
    return out;
}

std::string notOnRosterLine(const std::vector<std::string>& strangers) {
    std::string line = std::to_string(strangers.size()) + " hand-in" +
                       (strangers.size() == 1 ? "" : "s") + " not on the roster:";
    for (const std::string& n : strangers) line += " " + printableName(escapedName(n));
    return line;
}

std::vector<const RosterEntry*> rosterWithoutHandIn(const Roster& roster,
                                                    const std::vector<std::string>& names) {
    std::vector<const RosterEntry*> out;
    for (const RosterEntry& e : roster.entries)
        if (!handInNamed(names, e.handIn)) out.push_back(&e);
    return out;
}

}  // namespace sl
