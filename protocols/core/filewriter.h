#pragma once
// Writing our files atomically. QSaveFile writes into a temporary file and renames it over the
// target on commit(), so a writer that dies leaves the old file or the complete new one. Where the
// file system cannot give an unnamed temporary file (Linux without O_TMPFILE there, other
// systems), and for an instant during commit() everywhere, that temporary has a name,
// "<target>.XXXXXX" next to the target, and a writer killed at that point leaves it behind.
// removeStaleTemporaries() is called before each write of a file and clears such leftovers.
#include <QString>

#include <chrono>

namespace db::files {

// A temporary younger than this may belong to a writer that is still running (another
// drivebench process saving the same file): it is left alone.
constexpr std::chrono::seconds kStaleTemporaryAge { 60 };

// Removes the regular files next to `target` named "<target's file name>.XXXXXX", X being six
// ASCII letters (QSaveFile's and QTemporaryFile's pattern: random upper and lower case), last
// modified at least `minAge` ago. Six letters that read like a word ("backup", "BACKUP",
// "Backup") are a user's file, not a temporary: all lower case, all upper case and capitalised
// names are left alone (1 in 21 of Qt's random names looks like that and stays). Nothing else is
// touched: not the target, not other files' temporaries, not folders or symbolic links. Returns how
// many were removed; files that cannot be removed are skipped (the write itself then reports any
// real problem with the folder).
int removeStaleTemporaries(const QString &target, std::chrono::seconds minAge = kStaleTemporaryAge);

// `target` with the pattern of a temporary file next to it, for QTemporaryFile when a library
// writes by file name: removeStaleTemporaries() recognises what it leaves.
QString temporaryTemplate(const QString &target);

} // namespace db::files
