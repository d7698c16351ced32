// The ACU parameter description: loads, describes the parameters the way the inverter carries
// them over VABus/TCP, shows and takes physical values with the parameter's decimals.

#include "devices/bonfiglioli/acudescription.h"
#include "textlanguage.h"
#include "vabus/vabuscodec.h"

#include <QRegularExpression>
#include <QtTest>

using namespace db;

class TstAcuDescription : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void loads()
    {
        const auto loaded = bonfiglioli::loadAcuDictionary();
        QVERIFY2(loaded.ok(), qPrintable(loaded.error().toString()));
        QVERIFY(loaded.value().size() > 150);
    }

    void everyParameterCanTravelOverVabus()
    {
        const ObjectDictionary &d = bonfiglioli::acuDictionary();
        static const QRegularExpression reference(
            QStringLiteral(R"(manual|\(\d+(\.\d+)+\)|seed|§|inferred|\b(table|per|in) \d+\.\d)"),
            QRegularExpression::CaseInsensitiveOption);
        for (const ObjectDef &def : d.objects()) {
            QVERIFY2(vabus::isCarried(def.type), qPrintable(def.name));
            QVERIFY(def.address.index <= vabus::kMaxParameter);
            QVERIFY(def.address.sub <= vabus::kMaxReadDataSet);
            QVERIFY2(!reference.match(def.description).hasMatch(), qPrintable(def.description));
        }
    }

    void exampleParameters()
    {
        const ObjectDictionary &d = bonfiglioli::acuDictionary();
        const ObjectDef *rated = d.find(ObjectAddress(372, 2));
        QVERIFY(rated);
        QCOMPARE(rated->type, DataType::Unsigned16);
        QCOMPARE(rated->displayText(qulonglong(1390)), QStringLiteral("1390 rpm"));
        QVERIFY(bonfiglioli::hasDataSets(d, 372));

        const ObjectDef *ff2 = d.find(ObjectAddress(481, 1));
        QVERIFY(ff2);
        QCOMPARE(ff2->type, DataType::Integer32);
        QCOMPARE(ff2->decimals, 2);
        QCOMPARE(ff2->displayText(qlonglong(1000)), QStringLiteral("10.00 Hz"));
        QCOMPARE(ff2->parseText(QStringLiteral("10.5")).value(), QVariant(qlonglong(1050)));
        QCOMPARE(ff2->parseText(QStringLiteral("-0.01")).value(), QVariant(qlonglong(-1)));
        QVERIFY(!ff2->parseText(QStringLiteral("10.005")).ok());

        const ObjectDef *power = d.find(ObjectAddress(376, 4));
        QVERIFY(power);
        QCOMPARE(power->parseText(QStringLiteral("1.5")).value(), QVariant(qulonglong(15)));
        QVERIFY(power->storable);
        QVERIFY(!d.find(ObjectAddress(376, 0))->storable); // the four data sets are stored

        const ObjectDef *version = d.find(ObjectAddress(12, 0));
        QVERIFY(version);
        QCOMPARE(version->type, DataType::VisibleString);
        QVERIFY(!version->writable());
        QVERIFY(!bonfiglioli::hasDataSets(d, 12));

        const ObjectDef *status = d.find(ObjectAddress(411, 0));
        QVERIFY(status && !status->writable() && status->traceable);
        QCOMPARE(status->parseText(QStringLiteral("0x0237")).value(), QVariant(qulonglong(0x237)));
        const ObjectDef *control = d.find(ObjectAddress(410, 0));
        QVERIFY(control && control->writable() && !control->storable);

        const ObjectDef *behaviour = d.find(ObjectAddress(388, 0));
        QVERIFY(behaviour);
        QCOMPARE(behaviour->enumeration.value(1), QStringLiteral("fault"));
        QCOMPARE(behaviour->parseText(QStringLiteral("quick stop")).value(),
                 QVariant(qulonglong(3)));
        QVERIFY(!behaviour->parseText(QStringLiteral("6")).ok());

        QCOMPARE(d.find(ObjectAddress(1432, 1))->defaultValue, QVariant(qulonglong(172)));
        // Contradictory limits, as recommended: 414 takes 5, 1165 ends at 2^20 - 1.
        QVERIFY(d.find(ObjectAddress(414, 0))->parseText(QStringLiteral("5")).ok());
        QVERIFY(!d.find(ObjectAddress(1165, 0))->parseText(QStringLiteral("1048576")).ok());
        QVERIFY(d.find(ObjectAddress(1165, 0))->parseText(QStringLiteral("1048575")).ok());
        QCOMPARE(d.find(ObjectAddress(1459, 0))->type, DataType::Integer16);
    }

    // The German manual's names: every parameter has one, shown when the program speaks German;
    // the English name stays what parameter sets and scripts use.
    void germanNames()
    {
        const ObjectDictionary &d = bonfiglioli::acuDictionary();
        // Umlauts written out as two letters ("Verzoegerung") are not how German is written.
        static const QRegularExpression transliterated(
            QStringLiteral(R"(\bfuer\b|Ue|oeg|aend|aehl|aenge|Stoer)"));
        for (const ObjectDef &def : d.objects()) {
            const QString german = def.localNames.value(QStringLiteral("de"));
            QVERIFY2(!german.isEmpty(), qPrintable(def.name));
            QVERIFY2(!transliterated.match(german).hasMatch(), qPrintable(german));
        }
        const ObjectDef *status = d.find(ObjectAddress(411, 0));
        const ObjectDef *rated = d.find(ObjectAddress(372, 2));
        const ObjectDef *all = d.find(ObjectAddress(372, 0));
        QCOMPARE(status->displayName(), QStringLiteral("Status word"));
        QCOMPARE(rated->displayName(), QStringLiteral("Rated speed (data set 2)"));
        const test::TextLanguage german(QStringLiteral("de"));
        QCOMPARE(status->displayName(), QStringLiteral("Zustandswort"));
        QCOMPARE(rated->displayName(), QStringLiteral("Bemessungsdrehzahl (Datensatz 2)"));
        QCOMPARE(all->displayName(), QStringLiteral("Bemessungsdrehzahl (alle Datensätze)"));
        QCOMPARE(rated->displayObjectName(), QStringLiteral("Bemessungsdrehzahl"));
        QCOMPARE(d.find(ObjectAddress(421, 0))->displayName(),
                 QStringLiteral("Verzögerung (Rechtslauf)"));
        QCOMPARE(rated->name, QStringLiteral("Rated speed (data set 2)"));
    }

    // Selections and the bits of the status, control and warning words in German: the terms of
    // the German parameter descriptions; files keep the English ones.
    void germanValuesAndBits()
    {
        const ObjectDictionary &d = bonfiglioli::acuDictionary();
        const ObjectDef *busFault = d.find(ObjectAddress(388, 0));
        const ObjectDef *status = d.find(ObjectAddress(411, 0));
        QCOMPARE(busFault->localDisplayText(3), QStringLiteral("3 (quick stop)"));
        const test::TextLanguage german(QStringLiteral("de"));
        QCOMPARE(busFault->localDisplayText(3), QStringLiteral("3 (Schnellhalt)"));
        QCOMPARE(busFault->displayText(3), QStringLiteral("3 (quick stop)"));
        QCOMPARE(d.find(ObjectAddress(412, 2))->enumText(1),
                 QStringLiteral("Steuerung über Statemachine"));
        QCOMPARE(d.find(ObjectAddress(1454, 0))->enumText(6), QStringLiteral("Referenzfahrt"));
        QCOMPARE(status->bitFields.at(0).displayName(), QStringLiteral("Einschaltbereit"));
        QCOMPARE(status->bitFields.at(10).displayName(), QStringLiteral("Ziel erreicht"));
        QCOMPARE(d.find(ObjectAddress(410, 0))->bitFields.at(7).displayName(),
                 QStringLiteral("Fehler rücksetzen"));
        QCOMPARE(d.find(ObjectAddress(274, 0))->bitFields.at(5).displayName(),
                 QStringLiteral("Schleppfehler"));
        // Every value and bit has a German text, except names that are the same in German.
        static const QRegularExpression same(QStringLiteral("^(RxPDO\\d|SYNC)$"));
        int values = 0;
        int bits = 0;
        for (const ObjectDef &def : d.objects()) {
            for (auto it = def.enumeration.cbegin(); it != def.enumeration.cend(); ++it, ++values)
                QVERIFY2(same.match(*it).hasMatch() || def.enumText(it.key()) != *it,
                         qPrintable(QStringLiteral("%1: %2").arg(def.address.index).arg(*it)));
            for (const BitField &bit : def.bitFields) {
                ++bits;
                QVERIFY2(bit.displayName() != bit.name,
                         qPrintable(QStringLiteral("%1: %2").arg(def.address.index).arg(bit.name)));
            }
        }
        QVERIFY(values > 40 && bits > 40);
    }

    void faultTextsInGerman()
    {
        const ObjectDictionary &d = bonfiglioli::acuDictionary();
        QCOMPARE(d.errorText(0x1442), QStringLiteral("Positive software limit switch"));
        const test::TextLanguage german(QStringLiteral("de"));
        QCOMPARE(d.errorText(0x1442), QStringLiteral("Pos. SW-Endschalter"));
        QCOMPARE(d.errorText(0x1460), QStringLiteral("Pos. HW-Endsch.: unzulässige Signalquelle"));
        // A code whose table gives no German text: the English one.
        QVERIFY(d.errorText(0x2714).contains(QLatin1String("PLC")));
    }

    void faultCodes()
    {
        const ObjectDictionary &d = bonfiglioli::acuDictionary();
        const auto loss = d.errorCode(0x2714);
        QVERIFY(loss);
        QCOMPARE(loss->name, QStringLiteral("F2714"));
        QVERIFY(loss->text.contains(QLatin1String("PLC"), Qt::CaseInsensitive));
    }
};

QTEST_GUILESS_MAIN(TstAcuDescription)
#include "tst_acudescription.moc"
