#pragma once

// INI layer of the CiA 306 loader (edsloader.cpp): sections, keys, the object lists.
#include <QHash>
#include <QMap>
#include <QStringList>

namespace db::eds {

struct Section
{
    QString name; // as written
    int line = 0;
    QHash<QString, QString> values; // lower-case key -> value
    QString value(const char *key) const { return values.value(QLatin1String(key)); }
    bool has(const char *key) const { return values.contains(QLatin1String(key)); }
};

struct IniFile
{
    QMap<QString, Section> sections; // upper-case name -> section

    // Section and key names are case-insensitive (CiA 306 4.1); comments start with ';'.
    // Broken lines, keys outside sections, duplicate keys and sections become warnings (the
    // last value wins, sections merge).
    static IniFile parse(const QString &text, QStringList *warnings);
    const Section *section(const QString &name) const;
};

// Checks [MandatoryObjects]/[OptionalObjects]/[ManufacturerObjects] against the object sections
// present (CiA 306 4.5.2): counts, missing sections, unlisted objects.
void checkObjectLists(const IniFile &ini, const QMap<quint16, const Section *> &objects,
                      QStringList *warnings);

} // namespace db::eds
