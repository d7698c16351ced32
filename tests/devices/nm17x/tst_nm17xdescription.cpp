// NM17x descriptions: variant by identity, the objects of each variant, codes and texts.
#include "devices/nm17x/nm17xcodes.h"
#include "devices/nm17x/nm17xdescription.h"
#include "textlanguage.h"
#include "translations/language.h"

#include <QSet>
#include <QTest>

using namespace db;
using namespace db::nm17x;

class TstNm17xDescription : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void variantFromIdentity();
    void objectsPerVariant();
    void nodeDependentDefaults();
    void enumerationsAndBits();
    void errorPriorityAndTexts();
    void emcyTexts();
    void germanNames();
    void germanValuesAndBits();
};

void TstNm17xDescription::variantFromIdentity()
{
    QCOMPARE(variantOf(0xEC, 0x70), std::optional(Variant::Nm170));
    QCOMPARE(variantOf(0xEC, 0x71), std::optional(Variant::Nm172));
    QCOMPARE(variantOf(0xEC, 0x72), std::optional(Variant::Nm174));
    QVERIFY(!variantOf(0xEC, 0x73));
    QVERIFY(!variantOf(0x53B, 0x71)); // another vendor's product 71h
    QCOMPARE(variantName(Variant::Nm174), QStringLiteral("NM174"));
    QCOMPARE(deviceName(Variant::Nm172), QStringLiteral("NM172 Standard"));
    QCOMPARE(mspDeviceType(Variant::Nm174), 0x8481u);
    QCOMPARE(parseVariant(QStringLiteral("nm172")), std::optional(Variant::Nm172));
}

void TstNm17xDescription::objectsPerVariant()
{
    const ObjectDictionary nm170 = dictionary(Variant::Nm170);
    const ObjectDictionary nm172 = dictionary(Variant::Nm172);
    const ObjectDictionary nm174 = dictionary(Variant::Nm174);
    QVERIFY(!nm170.contains({ 0x204E, 1 })); // no motor, no status object
    QVERIFY(!nm170.contains({ 0x2043, 1 }));
    QVERIFY(nm172.contains({ 0x204E, 1 }));
    QVERIFY(!nm172.contains({ 0x2060, 1 })); // SSI sensor only on NM174
    QVERIFY(nm174.contains({ 0x2060, 3 }));
    QCOMPARE(nm170.find({ 0x2000, 3 })->maximum.toInt(), 3);
    QCOMPARE(nm172.find({ 0x2000, 3 })->maximum.toInt(), 5);
    QCOMPARE(nm172.find({ 0x1008, 0 })->defaultValue.toString(), QStringLiteral("NM172 Standard"));
    QCOMPARE(nm174.find({ 0x1018, 2 })->defaultValue.toUInt(), 0x72u);
    QCOMPARE(nm174.find({ 0x2005, 2 })->defaultValue.toInt(), 2);
    const ObjectDef *tolerance = nm172.find({ 0x2003, 0 });
    QCOMPARE(tolerance->unit, QStringLiteral("1/100 mm"));
    QCOMPARE(tolerance->defaultValue.toInt(), 5);
    QCOMPARE(nm172.find({ 0x2010, 0 })->minimum.toInt(), -99999);
    QCOMPARE(storageOf({ 0x2101, 0 }), Storage::Flash);
    QCOMPARE(storageOf({ 0x2020, 3 }), Storage::Ram);
    QCOMPARE(storageOf({ 0x2002, 0 }), Storage::Eeprom);
}

void TstNm17xDescription::nodeDependentDefaults()
{
    const ObjectDictionary d = dictionary(Variant::Nm172, 5);
    QCOMPARE(d.find({ 0x1014, 0 })->defaultValue.toUInt(), 0x85u);
    QCOMPARE(d.find({ 0x1401, 1 })->defaultValue.toUInt(), 0x40000305u);
    QCOMPARE(d.find({ 0x1800, 1 })->defaultValue.toUInt(), 0xC0000185u);
    QCOMPARE(d.find({ 0x1801, 1 })->defaultValue.toUInt(), 0x40000285u);
    QCOMPARE(d.find({ 0x1400, 1 })->defaultValue.toUInt(), 0x40000201u); // broadcast stays
}

void TstNm17xDescription::enumerationsAndBits()
{
    const ObjectDictionary d = dictionary(Variant::Nm172);
    QCOMPARE(d.find({ 0x2001, 0 })->displayText(1), QStringLiteral("1 (inch)"));
    QCOMPARE(d.find({ 0x2000, 3 })->enumeration.value(4), QStringLiteral("Uni-Loop"));
    QCOMPARE(d.find({ 0x2041, 1 })->enumeration.value(0), QStringLiteral("On"));
    QCOMPARE(d.find({ 0x2040, 4 })->enumeration.value(7), QStringLiteral("group 8"));
    QCOMPARE(d.find({ 0x2041, 3 })->parseText(QStringLiteral("ExternPosi")).value().toInt(), 2);
    const ObjectDef *errors = d.find({ 0x204E, 2 });
    QCOMPARE(errors->bitFields.size(), 12);
    QVERIFY(errors->bitFields.at(11).name.startsWith(QLatin1String("Er d")));
    QCOMPARE(d.find({ 0x204E, 1 })->bitFields.last().name, QStringLiteral("In Position"));
}

void TstNm17xDescription::errorPriorityAndTexts()
{
    // Er b, Er 1 and Er C at once: Er C first, then Er 1, then Er b.
    const QList<DisplayError> active = activeErrors((1u << 11) | (1u << 0) | (1u << 12));
    QCOMPARE(active.size(), 3);
    QCOMPARE(active.at(0).code, QStringLiteral("Er C"));
    QCOMPARE(active.at(1).code, QStringLiteral("Er 1"));
    QCOMPARE(active.at(2).code, QStringLiteral("Er b"));
    QVERIFY(errorText(1u << 8).startsWith(QLatin1String("Er 8 (setpoint above end limit MAX")));
    QCOMPARE(errorText(0), QString());
    QCOMPARE(statusText(status::Moving | status::InPosition),
             QStringLiteral("Moving, In Position"));
    QCOMPARE(statusText(0), QStringLiteral("-"));
}

void TstNm17xDescription::emcyTexts()
{
    QCOMPARE(emcyText(0x8230, 1), QStringLiteral("RxPDO2: invalid value in the control word"));
    QVERIFY(emcyText(0x8220, 2).contains(QLatin1String("FIFO")));
    QVERIFY(emcyText(0x8220, 9).contains(QLatin1String("conversion table"))); // unknown sub
    QCOMPARE(emcyText(0x1234, 0), QString());
    const ObjectDictionary d = dictionary(Variant::Nm170);
    QCOMPARE(d.errorText(0x8130), QStringLiteral("heartbeat error"));
}

// Every object carries the German manual's name, distinct within its object and written with
// umlauts; shown when the program speaks German.
void TstNm17xDescription::germanNames()
{
    const ObjectDictionary d = dictionary(Variant::Nm174);
    QMap<quint16, QSet<QString>> perObject;
    for (const ObjectDef &def : d.objects()) {
        const QString german = def.localNames.value(QStringLiteral("de"));
        QVERIFY2(!german.isEmpty(), qPrintable(def.name));
        QVERIFY2(!german.contains(QLatin1String("Groess")) && !german.contains(QLatin1String("ae"))
                     && !german.contains(QLatin1String("fuer")),
                 qPrintable(german));
        QSet<QString> &names = perObject[def.address.index];
        QVERIFY2(!names.contains(german), qPrintable(german));
        names.insert(german);
    }
    const ObjectDef *endMin = d.find({ 0x2043, 1 });
    QCOMPARE(endMin->displayName(), QStringLiteral("End limit MIN"));
    const test::TextLanguage german(QStringLiteral("de"));
    QCOMPARE(endMin->displayName(), QStringLiteral("Endlage MIN"));
    QCOMPARE(d.find({ 0x2000, 2 })->displayName(), QStringLiteral("Zählrichtung"));
    QCOMPARE(d.find({ 0x2020, 0 })->displayName(), QStringLiteral("Größter Subindex"));
    QCOMPARE(d.find({ 0x6004, 0 })->displayName(), QStringLiteral("Position (Istwert)"));
    QCOMPARE(endMin->name, QStringLiteral("End limit MIN"));
}

// With the German translation installed, a dictionary built then shows the values and bits in
// German, and keeps the English ones for files and the command line.
void TstNm17xDescription::germanValuesAndBits()
{
    QVERIFY(i18n::installTranslations(*QCoreApplication::instance(), QStringLiteral("de")));
    const ObjectDictionary d = dictionary(Variant::Nm174);
    const ObjectDef *function = d.find({ 0x2041, 3 });
    QCOMPARE(function->enumText(0), QStringLiteral("Standard / Oszillieren"));
    QCOMPARE(function->displayText(0), QStringLiteral("0 (Standard / Oscillating)"));
    QCOMPARE(d.find({ 0x204D, 3 })->localDisplayText(21), QStringLiteral("21 (links langsam)"));
    QCOMPARE(d.find({ 0x2040, 4 })->enumText(2), QStringLiteral("Gruppe 3"));
    const ObjectDef *status = d.find({ 0x204E, 1 });
    QCOMPARE(status->bitFields.at(0).displayName(), QStringLiteral("In Bewegung"));
    QCOMPARE(status->bitFields.at(0).name, QStringLiteral("Moving"));
    const ObjectDef *errors = d.find({ 0x204E, 2 });
    QCOMPARE(errors->bitFields.at(0).displayName(), QStringLiteral("Er 1 Endlage MAX verletzt"));
    QCOMPARE(errors->bitFields.at(0).name, QStringLiteral("Er 1 end limit MAX violated"));
    QVERIFY(i18n::installTranslations(*QCoreApplication::instance(), QStringLiteral("en")));
    QCOMPARE(function->enumText(0), QStringLiteral("Standard / Oscillating"));
}

QTEST_GUILESS_MAIN(TstNm17xDescription)
#include "tst_nm17xdescription.moc"
