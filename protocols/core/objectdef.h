#pragma once

#include "addressformat.h"
#include "datatype.h"
#include "objectaddress.h"
#include "valuecodec.h"

#include <QList>
#include <QMap>
#include <QVariant>

namespace db {

enum class Access { ReadOnly, WriteOnly, ReadWrite, Const };

// Texts of a device in further languages than English, by language code ("de" -> "Statuswort"):
// the terms of the device's own manuals. The English text stays the one that files, exports and
// scripts use; these are what people read.
using LocalTexts = QMap<QString, QString>;

// The language device texts are shown in: the one the installed translation speaks ("de"), "en"
// without a translation. Follows a language change at once.
QString textLanguage();
// `local`'s text for textLanguage(), else `english`.
QString localText(const QString &english, const LocalTexts &local);

namespace access {
QString name(Access access); // "ro", "wo", "rw", "const"
std::optional<Access> fromName(const QString &text);
} // namespace access

// A named group of bits inside a word (e.g. 6041h bit 10 "target reached").
struct BitField
{
    int bit = 0;
    int width = 1;
    QString name;
    LocalTexts localNames = {}; // name in further languages

    QString displayName() const { return localText(name, localNames); }
};

// Static metadata of one object (sub-index): what it is, never its current value
// (ARCHITECTURE.md habit 4: definition separate from value).
struct ObjectDef
{
    ObjectAddress address;
    QString name; // of this sub-index, e.g. "Statusword" or "Min position limit"
    QString objectName; // of the whole object for records/arrays; empty when the same as name
    DataType type = DataType::Unsigned32;
    Access access = Access::ReadWrite;
    QString unit;
    double factor = 1.0; // physical = raw * factor + offset
    double offset = 0.0;
    // Fixed decimal places of a fixed-point parameter (inverter parameter lists: raw = value x
    // 10^decimals, factor = 10^-decimals): its text is the physical value with exactly these
    // decimals ("10.00"), and text typed for it is a physical value. -1: not a fixed-point
    // parameter (text is the raw value).
    int decimals = -1;
    QVariant defaultValue; // raw values; invalid = unknown / no limit
    QVariant minimum;
    QVariant maximum;
    QMap<qlonglong, QString> enumeration;
    QList<BitField> bitFields;
    bool storable = false; // part of a parameter set (saved by 1010h)
    bool pdoMappable = false;
    bool traceable = false; // worth offering as a scope channel
    QString description;
    LocalTexts localNames = {}; // name in further languages
    LocalTexts localObjectNames = {}; // objectName in further languages
    QMap<qlonglong, LocalTexts> localEnumeration = {}; // enumeration texts in further languages
    LocalTexts localUnits = {}; // unit in further languages, for units that are words ("units")

    // name and objectName in the language the program speaks (see textLanguage()).
    QString displayName() const { return localText(name, localNames); }
    QString displayObjectName() const { return localText(objectName, localObjectNames); }
    QString displayUnit() const { return localText(unit, localUnits); }
    // The enumeration's text for `value` in the language the program speaks; empty when the
    // value has none.
    QString enumText(qlonglong value) const;
    // The enumeration with the texts in the language the program speaks.
    QMap<qlonglong, QString> displayEnumeration() const;

    bool readable() const { return access != Access::WriteOnly; }
    bool writable() const { return access == Access::ReadWrite || access == Access::WriteOnly; }

    // Type conversion, type range and the object's own min/max in one step. Errors name the
    // object's address as `format` writes it.
    Result<QVariant> validate(const QVariant &value,
                              const AddressFormat &format = AddressFormat::canopen()) const;
    // User text -> raw, accepting enumeration names (English and the program's language) as
    // well as numbers (physical values for fixed-point parameters, see decimals).
    Result<QVariant> parseText(const QString &text,
                               const AddressFormat &format = AddressFormat::canopen()) const;
    // "1 (Profile Position)", "0x0427", "1200 mm": enumeration texts in English, as files,
    // exports and the command line's fixed output write them.
    QString displayText(const QVariant &raw,
                        codec::TextFormat format = codec::TextFormat::Decimal) const;
    // The same for people: enumeration texts and unit in the language the program speaks.
    QString localDisplayText(const QVariant &raw,
                             codec::TextFormat format = codec::TextFormat::Decimal) const;
};

} // namespace db
