#pragma once

#include <QChar>
#include <QString>
#include <QStringView>

#include <vector>

namespace db::morse {

// International Morse code (ITU-R M.1677-1), written with '.' for a dit and '-' for a dah.
// Covers A-Z, 0-9 and the punctuation of ITU-R M.1677-1 section 1.1.3, which includes the
// characters of movingcap.md section 2.4 ('+' and ':').

// The code of a character (letters in either case), or an empty string when it has none.
QString codeFor(QChar c);

// The character of a code, or a null QChar when the code is not in the table.
QChar charFor(QStringView code);

// Nominal element lengths of `text` in units (ITU timing): alternating mark, gap, mark, gap, ...
// starting with a mark and ending with `lastGap` after the last mark; ' ' makes a word gap (7).
// Characters without a code are skipped.
std::vector<double> messageElements(const QString &text, double lastGap);

// Soft decision for a code that is not in the table: the character whose code has as many
// elements as `markUnits` (mark lengths in units) and the least sum of ln(length / nominal)^2,
// provided that sum exceeds the hard decision's by at most `maxExtraCost`. Null otherwise.
QChar nearestChar(const std::vector<double> &markUnits, double maxExtraCost);

} // namespace db::morse
