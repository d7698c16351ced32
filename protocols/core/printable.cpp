#include "printable.h"

namespace db {

namespace {

bool isBidiOrSeparator(char16_t u)
{
    return (u >= 0x202A && u <= 0x202E) || (u >= 0x2066 && u <= 0x2069) || u == 0x200E
        || u == 0x200F || u == 0x061C || u == 0x2028 || u == 0x2029;
}

bool needsEscape(char16_t u, LineBreaks lineBreaks)
{
    if (u >= 0x20 && u < 0x7F) // printable ASCII first: nearly every character is one
        return false;
    if (u < 0x20)
        return !(u == '\n' && lineBreaks == LineBreaks::Keep);
    return (u >= 0x7F && u <= 0x9F) || isBidiOrSeparator(u);
}

// Lower-case hex with at least `digits` digits, written in place: error messages quoting
// binary answers escape every byte, and a temporary string per byte made that the cost.
void appendHex(QString &out, const char *prefix, uint value, int digits)
{
    static constexpr char hex[] = "0123456789abcdef";
    out += QLatin1String(prefix);
    while (digits < 8 && (value >> (4 * digits)) != 0)
        ++digits;
    for (int shift = 4 * (digits - 1); shift >= 0; shift -= 4)
        out += QLatin1Char(hex[(value >> shift) & 0xF]);
}

void appendEscape(QString &out, char16_t u)
{
    switch (u) {
    case 0: // "\x00", not "\0": a digit after it would read as an octal escape ("\034")
        out += QLatin1String("\\x00");
        return;
    case '\t':
        out += QLatin1String("\\t");
        return;
    case '\n':
        out += QLatin1String("\\n");
        return;
    case '\r':
        out += QLatin1String("\\r");
        return;
    default:
        if (u < 0x80)
            appendHex(out, "\\x", u, 2);
        else
            appendHex(out, "\\u", u, 4);
    }
}

// Length of the UTF-8 sequence a lead byte starts; 0 for bytes that cannot start one (RFC 3629:
// C0, C1 and F5-FF never appear, continuation bytes never lead).
int sequenceLength(uchar lead)
{
    if (lead < 0x80)
        return 1;
    if (lead >= 0xC2 && lead <= 0xDF)
        return 2;
    if (lead >= 0xE0 && lead <= 0xEF)
        return 3;
    if (lead >= 0xF0 && lead <= 0xF4)
        return 4;
    return 0;
}

// The range the second byte must lie in, which excludes overlong forms, surrogates and code
// points above U+10FFFF (RFC 3629 section 4).
bool secondByteFits(uchar lead, uchar second)
{
    switch (lead) {
    case 0xE0:
        return second >= 0xA0 && second <= 0xBF;
    case 0xED:
        return second >= 0x80 && second <= 0x9F;
    case 0xF0:
        return second >= 0x90 && second <= 0xBF;
    case 0xF4:
        return second >= 0x80 && second <= 0x8F;
    default:
        return second >= 0x80 && second <= 0xBF;
    }
}

bool isContinuation(uchar b)
{
    return (b & 0xC0) == 0x80;
}

} // namespace

bool isPrintable(QStringView text, LineBreaks lineBreaks)
{
    for (qsizetype i = 0; i < text.size(); ++i) {
        const char16_t u = text[i].unicode();
        if (u >= 0x20 && u < 0x7F)
            continue;
        if (QChar::isHighSurrogate(u) && i + 1 < text.size()
            && QChar::isLowSurrogate(text[i + 1].unicode())) {
            ++i;
            continue;
        }
        if (QChar::isSurrogate(u) || needsEscape(u, lineBreaks))
            return false;
    }
    return true;
}

QString printable(QStringView text, LineBreaks lineBreaks)
{
    if (isPrintable(text, lineBreaks))
        return text.toString();
    QString out;
    out.reserve(text.size() + 16);
    for (qsizetype i = 0; i < text.size(); ++i) {
        const char16_t u = text[i].unicode();
        if (u >= 0x20 && u < 0x7F) {
            out += text[i];
        } else if (QChar::isHighSurrogate(u) && i + 1 < text.size()
                   && QChar::isLowSurrogate(text[i + 1].unicode())) {
            out += text[i];
            out += text[++i];
        } else if (QChar::isSurrogate(u) || needsEscape(u, lineBreaks)) {
            appendEscape(out, u);
        } else {
            out += text[i];
        }
    }
    return out;
}

QString printable(QByteArrayView bytes, LineBreaks lineBreaks)
{
    QString decoded;
    decoded.reserve(bytes.size());
    const qsizetype n = bytes.size();
    qsizetype i = 0;
    while (i < n) {
        const uchar lead = uchar(bytes[i]);
        const int length = sequenceLength(lead);
        if (length == 1) {
            decoded += QChar(lead);
            ++i;
            continue;
        }
        bool valid = length > 0 && i + length <= n && secondByteFits(lead, uchar(bytes[i + 1]));
        for (int k = 2; valid && k < length; ++k)
            valid = isContinuation(uchar(bytes[i + k]));
        if (!valid) {
            appendHex(decoded, "\\x", lead, 2);
            ++i;
            continue;
        }
        char32_t cp = lead & (0xFF >> (length + 1));
        for (int k = 1; k < length; ++k)
            cp = (cp << 6) | (uchar(bytes[i + k]) & 0x3F);
        for (const QChar c : QChar::fromUcs4(cp))
            decoded += c;
        i += length;
    }
    return printable(QStringView(decoded), lineBreaks);
}

qsizetype completeUtf8Prefix(QByteArrayView bytes)
{
    const qsizetype n = bytes.size();
    for (qsizetype k = 1; k <= 3 && k <= n; ++k) {
        const uchar b = uchar(bytes[n - k]);
        if (isContinuation(b))
            continue;
        return sequenceLength(b) > k ? n - k : n;
    }
    return n;
}

QString oneLine(QStringView text, qsizetype maxChars)
{
    QString out;
    for (const QChar c : text) {
        if (out.size() >= maxChars) {
            out += QStringLiteral("...");
            break;
        }
        if (c.unicode() < 0x20 || c.unicode() == 0x7F)
            out += QStringLiteral("\\x%1").arg(c.unicode(), 2, 16, QLatin1Char('0'));
        else
            out += c;
    }
    return out;
}

} // namespace db
