#pragma once

#include <QByteArrayView>
#include <QString>
#include <QStringView>

namespace db {

// Whether a line feed in quoted text stays a line feed (multi-line report bodies written by
// drivebench itself) or becomes "\n" like every other control character (anything that must
// stay on one line: error messages, values, names).
enum class LineBreaks { Escape, Keep };

// Text quoted from outside (device answers, file contents, file names) made safe to show on a
// terminal, in a log console or in a report: control characters cannot clear the screen, move
// the cursor, overwrite a line ("\r" + fake "OK"), cut the text (NUL) or reverse its direction.
//
// Replaced by a visible escape:
//   NUL -> "\x00"; TAB, CR, LF -> "\t", "\r", "\n" (LF kept with LineBreaks::Keep);
//   other C0 controls and DEL -> "\xNN" (ESC -> "\x1b", so "ESC [2J" shows as "\x1b[2J");
//   C1 controls U+0080-U+009F, bidi embeddings/overrides/isolates U+202A-U+202E and
//   U+2066-U+2069, the marks U+200E, U+200F, U+061C, the line/paragraph separators U+2028,
//   U+2029 and unpaired surrogates -> "\uNNNN".
// Everything else passes unchanged (umlauts, "µ", "°", CJK, emoji). A backslash is not
// escaped: the result is for people, not for parsing back, and the function is idempotent, so
// text escaped once (an Error message) can pass through another boundary unchanged.
QString printable(QStringView text, LineBreaks lineBreaks = LineBreaks::Escape);

// Bytes read from outside, decoded as UTF-8; each byte that is not part of a well-formed UTF-8
// sequence (RFC 3629: no overlong forms, surrogates or code points above U+10FFFF) becomes
// "\xNN", then the text is escaped as above.
QString printable(QByteArrayView bytes, LineBreaks lineBreaks = LineBreaks::Escape);

// One line of outside text for a log line or a file comment: C0 controls and DEL as "\xNN"
// (every byte value visible, "\x00" for NUL), at most maxChars characters, "..." marking a cut.
QString oneLine(QStringView text, qsizetype maxChars);

// True when printable(text, lineBreaks) would return text unchanged.
bool isPrintable(QStringView text, LineBreaks lineBreaks = LineBreaks::Escape);

// The length of the longest prefix of bytes that does not end inside a UTF-8 sequence that more
// bytes could still complete: a writer that receives text in pieces escapes up to there and
// keeps the rest (at most 3 bytes) for the next piece.
qsizetype completeUtf8Prefix(QByteArrayView bytes);

} // namespace db
