#include "edsinifile.h"

#include "devicedescription.h"

#include <QCoreApplication>
#include <QSet>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db::eds {

namespace {
constexpr int kMaxListedObjects = 12; // objects named in one "not listed" warning
} // namespace

const Section *IniFile::section(const QString &name) const
{
    const auto it = sections.constFind(name.toUpper());
    return it == sections.cend() ? nullptr : &it.value();
}

IniFile IniFile::parse(const QString &text, QStringList *warnings)
{
    IniFile ini;
    auto warn = [warnings](const QString &where, const QString &what) {
        *warnings << where + QLatin1String(": ") + what;
    };
    Section *current = nullptr;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (int i = 0; i < lines.size(); ++i) {
        const QString line = lines.at(i).trimmed(); // also drops the CR of CRLF
        // Made only for a warning: translating and formatting it for every line was most of
        // the time spent reading a file.
        const auto where = [i] {
            return Tr::tr("line %1").arg(i + 1);
        };
        if (line.isEmpty() || line.startsWith(QLatin1Char(';'))
            || line.startsWith(QLatin1Char('#')))
            continue;
        if (line.startsWith(QLatin1Char('['))) {
            const qsizetype close = line.indexOf(QLatin1Char(']'));
            if (close < 0) {
                warn(where(), Tr::tr("broken section header '%1'; skipped").arg(line));
                current = nullptr;
                continue;
            }
            const QString name = line.mid(1, close - 1).trimmed();
            const QString key = name.toUpper();
            if (ini.sections.contains(key))
                warn(where(), Tr::tr("section [%1] appears again; merged").arg(name));
            current = &ini.sections[key];
            if (current->name.isEmpty()) {
                current->name = name;
                current->line = i + 1;
            }
            continue;
        }
        const qsizetype eq = line.indexOf(QLatin1Char('='));
        if (eq <= 0 || !current) {
            warn(where(),
                 Tr::tr("'%1' is not a key=value line in a section; ignored").arg(line.left(40)));
            continue;
        }
        const QString key = line.left(eq).trimmed().toLower();
        if (current->values.contains(key))
            warn(where(),
                 Tr::tr("[%1] %2 given twice; the last one is used")
                     .arg(current->name, line.left(eq).trimmed()));
        current->values.insert(key, line.mid(eq + 1).trimmed());
    }
    return ini;
}

void checkObjectLists(const IniFile &ini, const QMap<quint16, const Section *> &objects,
                      QStringList *warnings)
{
    auto warn = [warnings](const QString &where, const QString &what) {
        *warnings << where + QLatin1String(": ") + what;
    };
    QSet<quint16> listed;
    bool anyList = false;
    for (const char *name : { "MandatoryObjects", "OptionalObjects", "ManufacturerObjects" }) {
        const Section *list = ini.section(QLatin1String(name));
        if (!list)
            continue;
        anyList = true;
        const QString where = QStringLiteral("[%1]").arg(QLatin1String(name));
        const int stated =
            int(description::parseInteger(list->value("supportedobjects"), true).value_or(-1));
        int entries = 0;
        for (auto it = list->values.cbegin(); it != list->values.cend(); ++it) {
            if (it.key() == QLatin1String("supportedobjects"))
                continue;
            ++entries;
            const auto index = description::parseInteger(it.value(), true);
            if (!index || *index < 0 || *index > 0xFFFF) {
                warn(where, Tr::tr("entry %1=%2 is not an index").arg(it.key(), *it));
                continue;
            }
            listed.insert(quint16(*index));
            if (!objects.contains(quint16(*index)))
                warn(where,
                     Tr::tr("lists %1 but there is no [%2] section")
                         .arg(it.value())
                         .arg(*index, 4, 16, QLatin1Char('0')));
        }
        if (stated != entries)
            warn(where,
                 Tr::tr("SupportedObjects=%1 but %2 entries are listed")
                     .arg(list->value("supportedobjects"))
                     .arg(entries));
    }
    if (!anyList) {
        warn(Tr::tr("object lists"),
             QStringLiteral("no [MandatoryObjects]/[OptionalObjects]/[ManufacturerObjects]; "
                            "every object section is loaded"));
        return;
    }
    QStringList unlisted;
    for (auto it = objects.cbegin(); it != objects.cend(); ++it) {
        if (it.key() >= 0x1000 && !listed.contains(it.key()))
            unlisted << QStringLiteral("%1").arg(it.key(), 4, 16, QLatin1Char('0')).toUpper();
    }
    if (!unlisted.isEmpty()) {
        const qsizetype n = unlisted.size();
        if (n > kMaxListedObjects)
            unlisted = unlisted.mid(0, kMaxListedObjects) << QStringLiteral("...");
        warn(Tr::tr("object lists"),
             QStringLiteral("%1 object(s) not listed in any object list, loaded anyway: %2")
                 .arg(n)
                 .arg(unlisted.join(QLatin1String(", "))));
    }
}

} // namespace db::eds
