#include "course/roster.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "course/student_grade.h"
#include "io/files.h"
#include "render/request.h"

namespace sl {

namespace {

constexpr std::size_t kMaxRosterBytes = 16u << 20;
constexpr std::size_t kMaxRosterRows = 100000;

struct CsvRecord {
    std::vector<std::string> fields;
    int line = 0;  // the line it starts on
};

// RFC 4180 records of `text` (CRLF or LF line ends; a quoted field may hold commas, quotes
// doubled and line breaks). Blank lines are skipped. `fail(line, what)` throws.
template <class Fail>
std::vector<CsvRecord> csvRecords(const std::string& text, Fail fail) {
    std::vector<CsvRecord> out;
    int line = 1;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == '\n' || (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) {
            i += text[i] == '\r' ? 2 : 1;  // a blank line
            ++line;
            continue;
        }
        CsvRecord rec;
        rec.line = line;
        for (;;) {  // one field per round
            std::string field;
            if (i < text.size() && text[i] == '"') {
                const int opened = line;
                for (++i;; ++i) {
                    if (i >= text.size()) fail(opened, "a quoted field is never closed");
                    if (text[i] == '"') {
                        if (i + 1 < text.size() && text[i + 1] == '"') {
                            field += '"';
                            ++i;
                            continue;
                        }
                        ++i;
                        break;
                    }
                    if (text[i] == '\n') ++line;
                    field += text[i];
                }
                if (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r')
                    fail(line, "text after a closing quote (a quote inside a field is doubled)");
            } else {
                while (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r') {
                    if (text[i] == '"')
                        fail(line,
                             "a quote inside an unquoted field (quote the field, double "
                             "the quote)");
                    field += text[i++];
                }
            }
            rec.fields.push_back(field);
            if (i < text.size() && text[i] == ',') {
                ++i;
                continue;
            }
            if (i < text.size() && text[i] == '\r') {
                if (i + 1 >= text.size() || text[i + 1] != '\n')
                    fail(line, "a carriage return that does not end a line");
                ++i;
            }
            if (i < text.size() && text[i] == '\n') {
                ++i;
                ++line;
            }
            break;
        }
        out.push_back(std::move(rec));
        if (out.size() > kMaxRosterRows + 1)
            fail(line, "more than " + std::to_string(kMaxRosterRows) + " students");
    }
    return out;
}

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
    return nullptr;
}

Roster parseRoster(const std::string& input, const std::string& origin) {
    auto fail = [&](int line, const std::string& what) {
        throw UsageError(printableName(origin) + ": line " + std::to_string(line) + ": " + what);
    };
    std::string text = input;
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a byte order mark
    if (validUtf8(text) != text) {
        std::size_t at = 0;
        std::string good = validUtf8(text);
        while (at < text.size() && at < good.size() && text[at] == good[at]) ++at;
        fail(int(std::count(text.begin(), text.begin() + long(at), '\n')) + 1,
             "not UTF-8 (save the file as UTF-8)");
    }
    std::vector<CsvRecord> records = csvRecords(text, fail);
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
    std::string err = readRegularFile(path, kMaxRosterBytes, text);
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

StudentRecord noHandInRecord(const Assignment& a, const RosterEntry& e) {
    StudentWork none;
    none.name = e.handIn;
    GradingPlan plan = planStudent(a, none, std::nullopt);
    std::vector<StageRecord> stages;
    for (const StagePlan& p : plan.stages) stages.push_back(stageRecord(p, nullptr, ""));
    none.notes.push_back("no hand-in");
    StudentRecord r = buildRecord(plan, none, stages, 0);
    r.roster = e.who;
    return r;
}

std::vector<std::string> handInsNotOnRoster(const Roster& roster,
                                            const std::vector<std::string>& names) {
    std::vector<std::string> out;
    for (const std::string& n : names)
        if (!roster.find(n)) out.push_back(n);
    return out;
}

std::vector<const RosterEntry*> rosterWithoutHandIn(const Roster& roster,
                                                    const std::vector<std::string>& names) {
    std::vector<const RosterEntry*> out;
    for (const RosterEntry& e : roster.entries)
        if (std::find(names.begin(), names.end(), e.handIn) == names.end()) out.push_back(&e);
    return out;
}

}  // namespace sl
