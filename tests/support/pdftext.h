#pragma once

// The text of a PDF written by Qt's PDF engine (QPdfWriter), for tests: Qt draws text as glyph
// ids of embedded font subsets (Identity-H, two bytes a glyph) in Flate-compressed content
// streams, and gives each font a ToUnicode CMap. This inflates the streams, reads each font's
// CMap and decodes the glyphs of every Tj/TJ in drawing order. Runs are joined as they are (Qt
// draws a space as a glyph of its own), white space becomes one space, and ligatures are split
// (NFKC: "ﬁ" is "fi"). Not a general PDF reader: enough for files Qt wrote.

#include <QByteArray>
#include <QHash>
#include <QRegularExpression>
#include <QString>
#include <QtEndian>

namespace db::test {

namespace pdfdetail {

// Object number -> its body (between "N 0 obj" and "endobj"), streams inflated.
struct Object
{
    QByteArray dict;
    QByteArray stream; // inflated when /FlateDecode
};

inline QByteArray inflate(const QByteArray &deflated)
{
    // qUncompress wants the expected size first (big endian); it grows beyond it if needed.
    QByteArray withSize(4, '\0');
    qToBigEndian<quint32>(quint32(qMax<qsizetype>(deflated.size() * 8, 1024)), withSize.data());
    return qUncompress(withSize + deflated);
}

inline QHash<int, Object> objects(const QByteArray &pdf)
{
    QHash<int, Object> out;
    static const QRegularExpression start(QStringLiteral("(\\d+) 0 obj"));
    const QString latin = QString::fromLatin1(pdf);
    auto it = start.globalMatch(latin);
    while (it.hasNext()) {
        const auto m = it.next();
        const qsizetype from = m.capturedEnd();
        const qsizetype end = pdf.indexOf("endobj", from);
        if (end < 0)
            break;
        QByteArray body = pdf.mid(from, end - from);
        Object o;
        const qsizetype s = body.indexOf("stream");
        if (s >= 0 && body.indexOf("endstream") > s) {
            o.dict = body.left(s);
            qsizetype data = s + 6;
            if (body.at(data) == '\r')
                ++data;
            if (body.at(data) == '\n')
                ++data;
            QByteArray raw = body.mid(data, body.lastIndexOf("endstream") - data);
            o.stream = o.dict.contains("/FlateDecode") ? inflate(raw) : raw;
        } else {
            o.dict = body;
        }
        out.insert(m.captured(1).toInt(), o);
    }
    return out;
}

// A ToUnicode CMap: glyph id -> text.
inline QHash<quint32, QString> cmap(const QByteArray &stream)
{
    QHash<quint32, QString> map;
    const QString text = QString::fromLatin1(stream);
    const auto unicode = [](const QString &hex) {
        QString s;
        for (qsizetype i = 0; i + 4 <= hex.size(); i += 4)
            s += QChar(char16_t(hex.mid(i, 4).toUShort(nullptr, 16)));
        return s;
    };
    static const QRegularExpression chars(QStringLiteral("beginbfchar(.*?)endbfchar"),
                                          QRegularExpression::DotMatchesEverythingOption);
    static const QRegularExpression pair(QStringLiteral("<([0-9A-Fa-f]+)>\\s*<([0-9A-Fa-f]+)>"));
    for (auto b = chars.globalMatch(text); b.hasNext();) {
        const QString block = b.next().captured(1);
        for (auto p = pair.globalMatch(block); p.hasNext();) {
            const auto m = p.next();
            map.insert(m.captured(1).toUInt(nullptr, 16), unicode(m.captured(2)));
        }
    }
    static const QRegularExpression ranges(QStringLiteral("beginbfrange(.*?)endbfrange"),
                                           QRegularExpression::DotMatchesEverythingOption);
    static const QRegularExpression range(
        QStringLiteral("<([0-9A-Fa-f]+)>\\s*<([0-9A-Fa-f]+)>\\s*(\\[[^\\]]*\\]|<[0-9A-Fa-f]+>)"));
    static const QRegularExpression hexString(QStringLiteral("<([0-9A-Fa-f]+)>"));
    for (auto b = ranges.globalMatch(text); b.hasNext();) {
        const QString block = b.next().captured(1);
        for (auto r = range.globalMatch(block); r.hasNext();) {
            const auto m = r.next();
            const quint32 first = m.captured(1).toUInt(nullptr, 16);
            const quint32 last = m.captured(2).toUInt(nullptr, 16);
            const QString target = m.captured(3);
            if (target.startsWith(QLatin1Char('['))) {
                quint32 g = first;
                for (auto h = hexString.globalMatch(target); h.hasNext() && g <= last; ++g)
                    map.insert(g, unicode(h.next().captured(1)));
            } else {
                const QString base = unicode(target.mid(1, target.size() - 2));
                for (quint32 g = first; g <= last && !base.isEmpty(); ++g) {
                    QString s = base;
                    s[s.size() - 1] = QChar(char16_t(base.back().unicode() + (g - first)));
                    map.insert(g, s);
                }
            }
        }
    }
    return map;
}

} // namespace pdfdetail

inline QString pdfText(const QByteArray &pdf)
{
    using namespace pdfdetail;
    const QHash<int, Object> all = objects(pdf);
    // Font object -> its glyph map, through /ToUnicode N 0 R.
    static const QRegularExpression toUnicode(QStringLiteral("/ToUnicode\\s+(\\d+)\\s+0\\s+R"));
    static const QRegularExpression descendant(
        QStringLiteral("/DescendantFonts\\s*\\[\\s*(\\d+)\\s+0\\s+R"));
    QHash<int, QHash<quint32, QString>> fonts;
    for (auto it = all.cbegin(); it != all.cend(); ++it) {
        const auto m = toUnicode.match(QString::fromLatin1(it->dict));
        if (m.hasMatch())
            fonts.insert(it.key(), cmap(all.value(m.captured(1).toInt()).stream));
    }
    // Resource names -> font objects ("/F5 5 0 R" in the pages' /Font dictionaries).
    QHash<QString, int> names;
    static const QRegularExpression resource(QStringLiteral("/(\\w+)\\s+(\\d+)\\s+0\\s+R"));
    for (const Object &o : all) {
        const QString dict = QString::fromLatin1(o.dict);
        const qsizetype font = dict.indexOf(QLatin1String("/Font"));
        if (font < 0 || dict.contains(QLatin1String("/Type /Font")))
            continue;
        for (auto r = resource.globalMatch(dict, font); r.hasNext();) {
            const auto m = r.next();
            if (fonts.contains(m.captured(2).toInt()))
                names.insert(m.captured(1), m.captured(2).toInt());
        }
    }
    QStringList runs;
    static const QRegularExpression ops(
        QStringLiteral("/(\\w+)\\s+[-\\d.]+\\s+Tf|(\\[[^\\]]*\\]|<[0-9A-Fa-f]*>)\\s*T[jJ]"));
    static const QRegularExpression hexString(QStringLiteral("<([0-9A-Fa-f]*)>"));
    for (const Object &o : all) {
        if (o.stream.isEmpty() || !o.stream.contains(" Tf"))
            continue;
        const QHash<quint32, QString> *map = nullptr;
        for (auto it = ops.globalMatch(QString::fromLatin1(o.stream)); it.hasNext();) {
            const auto m = it.next();
            if (!m.captured(1).isEmpty()) {
                const auto f = fonts.constFind(names.value(m.captured(1), -1));
                map = f == fonts.cend() ? nullptr : &*f;
                continue;
            }
            QString run;
            for (auto h = hexString.globalMatch(m.captured(2)); h.hasNext();) {
                const QString hex = h.next().captured(1);
                for (qsizetype i = 0; i + 4 <= hex.size(); i += 4) {
                    const quint32 glyph = hex.mid(i, 4).toUInt(nullptr, 16);
                    run += map ? map->value(glyph, QStringLiteral("?")) : QStringLiteral("?");
                }
            }
            runs << run;
        }
    }
    return runs.join(QString()).normalized(QString::NormalizationForm_KC).simplified();
}

} // namespace db::test
