// A class roster (`grade --roster roster.csv`, docs/assignment.md "Roster"): who each hand-in
// is. RFC 4180 CSV, UTF-8 with or without a byte order mark, a header row naming the columns
// id, name, email, hand-in (in that order), then one student per row. Each student's id, name
// and email go into their record (`roster`), grades.csv and their page; a student on the roster
// with no hand-in still gets a row ("no hand-in": every stage MISSING, 0 points).
#pragma once

#include <string>
#include <vector>

#include "grade/record.h"

namespace sl {

struct RosterEntry {
    RosterInfo who;      // id, name, email
    std::string handIn;  // the hand-in's name: a folder's name or a zip's stem
    int line = 0;        // where it starts in the file
};

struct Roster {
    std::vector<RosterEntry> entries;
    // The entry of hand-in `name`, or nullptr.
    const RosterEntry* find(const std::string& name) const;
};

// The roster in `text`; `origin` names it in errors. Throws UsageError (exit 2) "ORIGIN: line
// N: what" for anything else: a bad header, a wrong number of fields, a stray or unterminated
// quote, bytes that are not UTF-8, an empty id or hand-in, a hand-in or id given twice.
Roster parseRoster(const std::string& text, const std::string& origin);
// The roster at `path` (at most 16 MiB).
Roster loadRoster(const std::string& path);

// Gives `r` (hand-in `handIn`) its roster entry (none when it is not on the roster); true when
// that changed the record (it is then written again, so the kept record carries it).
bool attachRoster(const Roster& roster, const std::string& handIn, StudentRecord& r);

// The hand-ins in `names` that the roster does not list, and the roster's entries whose
// hand-in is not in `names`.
std::vector<std::string> handInsNotOnRoster(const Roster& roster,
                                            const std::vector<std::string>& names);
// The line naming `strangers`, hand-ins the roster does not list ("1 hand-in not on the roster:
// zed"), each as every output names a hand-in (a name that is not UTF-8 escaped byte by byte).
std::string notOnRosterLine(const std::vector<std::string>& strangers);
std::vector<const RosterEntry*> rosterWithoutHandIn(const Roster& roster,
                                                    const std::vector<std::string>& names);

}  // namespace sl
