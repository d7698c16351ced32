// Our JSON device descriptions: the built-in MovingCap one, and clear errors for broken files.
#include "core/objectdictionary.h"
#include "description/descriptionfile.h"
#include "resources/builtindescriptions.h"
#include "textlanguage.h"

#include <QRegularExpression>
#include <QTest>

using namespace db;

class TestDescriptionFile : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void movingCapDescriptionLoads();
    void movingCapObjectsFollowTheSpec();
    void movingCapErrorTexts();
    void namesInFurtherLanguages();
    void movingCapErrorTextsInGerman();
    void valuesAndBitsInFurtherLanguages();
    void movingCapValuesAndBitsInGerman();
    void builtinTextsAreForUsers();
    void brokenFilesGiveClearErrors_data();
    void brokenFilesGiveClearErrors();
    void missingFileNamesThePath();
};

void TestDescriptionFile::movingCapDescriptionLoads()
{
    const auto dict = resources::builtinDescription(QStringLiteral("movingcap_eth"));
    QVERIFY2(dict.ok(), qPrintable(dict.error().toString()));
    QVERIFY(dict->size() > 240);
    QCOMPARE(dict->identity.vendorId, 0x053Bu);
    QVERIFY(resources::builtinDescriptionNames().contains(QStringLiteral("movingcap_eth")));
    QCOMPARE(resources::movingCapDictionary().size(), dict->size());
}

void TestDescriptionFile::movingCapObjectsFollowTheSpec()
{
    const ObjectDictionary &dict = resources::movingCapDictionary();
    const ObjectDef *sw = dict.find(ObjectAddress(0x6041, 0));
    QVERIFY(sw);
    QCOMPARE(sw->type, DataType::Unsigned16);
    QCOMPARE(sw->access, Access::ReadOnly);
    QVERIFY(sw->bitFields.size() >= 11);
    // errata 12: 60FDh and 60FEh.1 hold bits 16+, so UNSIGNED32
    QCOMPARE(dict.find(ObjectAddress(0x60FD, 0))->type, DataType::Unsigned32);
    QCOMPARE(dict.find(ObjectAddress(0x60FE, 1))->type, DataType::Unsigned32);
    // errata 8/9: typo objects are not separate objects
    QVERIFY(!dict.contains(ObjectAddress(0x3403, 3)));
    QVERIFY(!dict.contains(ObjectAddress(0x3101, 4)));
    // all ten input function objects
    for (int in = 0; in < 10; ++in)
        QCOMPARE(dict.subObjects(quint16(0x3511 + in)).size(), 10);
    QCOMPARE(dict.find(ObjectAddress(0x6060, 0))->displayText(QVariant::fromValue(1LL)),
             QStringLiteral("1 (Profile position)"));
    QCOMPARE(dict.find(ObjectAddress(0x6060, 0))->parseText(QStringLiteral("homing")).value(),
             QVariant::fromValue(6LL));
    QCOMPARE(dict.find(ObjectAddress(0x6078, 0))->displayText(QVariant::fromValue(902LL)),
             QStringLiteral("90.2 %"));
    QVERIFY(!dict.find(ObjectAddress(0x3300, 5))->validate(181).ok());
    QVERIFY(dict.find(ObjectAddress(0x6083, 0))->storable);
    QVERIFY(!dict.find(ObjectAddress(0x6040, 0))->storable);
}

void TestDescriptionFile::movingCapErrorTexts()
{
    const ObjectDictionary &dict = resources::movingCapDictionary();
    QVERIFY(dict.errorText(0x3221).contains(QLatin1String("Under-voltage")));
    QCOMPARE(dict.errorText(0x2220), QStringLiteral("Over-current"));
    QCOMPARE(dict.errorCode(0x2220)->name, QStringLiteral("ERROR_OVER_CURRENT"));
    QCOMPARE(dict.errorText(0x8130), QStringLiteral("life guard or heartbeat error"));
    QCOMPARE(dict.errorText(0x3299), QStringLiteral("voltage inside the device"));
}

// "name_de", "object_de" and an error's "text_de" are what people read when the program speaks
// German; the English texts stay the names files use, and are shown in every other language.
void TestDescriptionFile::namesInFurtherLanguages()
{
    const QByteArray json = R"({"format":"drivebench-device-description","version":1,
        "objects":[{"index":"0x6041","sub":0,"type":"U16","name":"Statusword",
                    "name_de":"Statuswort"},
                   {"index":"0x2000","sub":1,"type":"U8","name":"Minimum","object":"Limits",
                    "name_de":"Minimum","object_de":"Grenzen","name_fr":"Minimum"},
                   {"index":"0x2001","sub":0,"type":"U8","name":"Plain"}],
        "errors":[{"code":"0x2220","name":"OVER","text":"Over-current","text_de":"Überstrom"}]})";
    const auto dict = parseJsonDescription(json, QStringLiteral("test.json"));
    QVERIFY2(dict.ok(), qPrintable(dict.error().toString()));
    const ObjectDef *sw = dict->find(ObjectAddress(0x6041, 0));
    const ObjectDef *min = dict->find(ObjectAddress(0x2000, 1));
    const ObjectDef *plain = dict->find(ObjectAddress(0x2001, 0));
    QCOMPARE(sw->localNames.value(QStringLiteral("de")), QStringLiteral("Statuswort"));
    QCOMPARE(min->localNames.size(), 2);

    QCOMPARE(textLanguage(), QStringLiteral("en"));
    QCOMPARE(sw->displayName(), QStringLiteral("Statusword"));
    QCOMPARE(min->displayObjectName(), QStringLiteral("Limits"));
    QCOMPARE(dict->errorText(0x2220), QStringLiteral("Over-current"));
    {
        const test::TextLanguage german(QStringLiteral("de"));
        QCOMPARE(textLanguage(), QStringLiteral("de"));
        QCOMPARE(sw->displayName(), QStringLiteral("Statuswort"));
        QCOMPARE(min->displayObjectName(), QStringLiteral("Grenzen"));
        QCOMPARE(plain->displayName(), QStringLiteral("Plain")); // no German name: English
        QCOMPARE(dict->errorText(0x2220), QStringLiteral("Überstrom"));
        QCOMPARE(sw->name, QStringLiteral("Statusword")); // what files and scripts use
    }
    {
        const test::TextLanguage italian(QStringLiteral("it"));
        QCOMPARE(sw->displayName(), QStringLiteral("Statusword"));
    }
    QCOMPARE(sw->displayName(), QStringLiteral("Statusword"));
}

// "enum_LANG" and a bit's "name_LANG" are what people read; files, the command line's fixed
// output and typed English names keep working.
void TestDescriptionFile::valuesAndBitsInFurtherLanguages()
{
    const QByteArray json = R"({"format":"drivebench-device-description","version":1,
        "objects":[{"index":"0x6060","sub":0,"type":"INTEGER8","name":"Modes of operation",
                    "enum":{"1":"Profile position","3":"Velocity","6":"Homing"},
                    "enum_de":{"1":"Positionierbetrieb","6":"Referenzierbetrieb"}},
                   {"index":"0x6041","sub":0,"type":"U16","name":"Statusword",
                    "bits":[{"bit":0,"name":"ready to switch on","name_de":"Einschaltbereit"},
                            {"bit":9,"name":"remote"}]}]})";
    const auto dict = parseJsonDescription(json, QStringLiteral("test.json"));
    QVERIFY2(dict.ok(), qPrintable(dict.error().toString()));
    const ObjectDef *mode = dict->find(ObjectAddress(0x6060, 0));
    const ObjectDef *sw = dict->find(ObjectAddress(0x6041, 0));
    QCOMPARE(mode->localDisplayText(1), QStringLiteral("1 (Profile position)"));
    QCOMPARE(sw->bitFields.at(0).displayName(), QStringLiteral("ready to switch on"));
    {
        const test::TextLanguage german(QStringLiteral("de"));
        QCOMPARE(mode->localDisplayText(1), QStringLiteral("1 (Positionierbetrieb)"));
        QCOMPARE(mode->localDisplayText(3), QStringLiteral("3 (Velocity)")); // none: English
        QCOMPARE(mode->enumText(6), QStringLiteral("Referenzierbetrieb"));
        QCOMPARE(mode->displayEnumeration().value(6), QStringLiteral("Referenzierbetrieb"));
        QCOMPARE(mode->displayText(1), QStringLiteral("1 (Profile position)")); // files, CLI
        QCOMPARE(mode->enumeration.value(6), QStringLiteral("Homing"));
        QCOMPARE(sw->bitFields.at(0).displayName(), QStringLiteral("Einschaltbereit"));
        QCOMPARE(sw->bitFields.at(1).displayName(), QStringLiteral("remote"));
        QCOMPARE(sw->bitFields.at(0).name, QStringLiteral("ready to switch on"));
        // Either language's name is accepted where a value is typed.
        QCOMPARE(mode->parseText(QStringLiteral("referenzierbetrieb")).value().toInt(), 6);
        QCOMPARE(mode->parseText(QStringLiteral("Homing")).value().toInt(), 6);
    }
    QCOMPARE(mode->enumText(6), QStringLiteral("Homing"));
}

// The drive's German manual and the German CiA 402 terms for its values and bits.
void TestDescriptionFile::movingCapValuesAndBitsInGerman()
{
    const ObjectDictionary &dict = resources::movingCapDictionary();
    const test::TextLanguage german(QStringLiteral("de"));
    const ObjectDef *modes = dict.find(ObjectAddress(0x6061, 0));
    QCOMPARE(modes->enumText(1), QStringLiteral("Positionierbetrieb"));
    QCOMPARE(modes->enumText(6), QStringLiteral("Referenzierbetrieb"));
    QCOMPARE(dict.find(ObjectAddress(0x6098, 0))->enumText(-18),
             QStringLiteral("Anschlagsreferenzierung positiv"));
    const ObjectDef *position = dict.find(ObjectAddress(0x6064, 0));
    QCOMPARE(position->localDisplayText(1200), QStringLiteral("1200 Einheiten"));
    QCOMPARE(position->displayText(1200), QStringLiteral("1200 units"));
    const ObjectDef *sw = dict.find(ObjectAddress(0x6041, 0));
    QCOMPARE(sw->bitFields.at(10).displayName(), QStringLiteral("Ziel erreicht"));
    // Every value and bit has a German text, except names that are the same in German
    // (IN1, OUT1) and the controller names (Rabbit, Hedgehog, Float).
    static const QRegularExpression same(
        QStringLiteral("^(IN|OUT)\\d+$|^(Rabbit|Hedgehog|Float)$"));
    for (const ObjectDef &def : dict.objects()) {
        for (auto it = def.enumeration.cbegin(); it != def.enumeration.cend(); ++it)
            QVERIFY2(same.match(*it).hasMatch() || def.enumText(it.key()) != *it,
                     qPrintable(QStringLiteral("%1: %2").arg(def.address.toString(), *it)));
        for (const BitField &bit : def.bitFields)
            QVERIFY2(same.match(bit.name).hasMatch() || bit.displayName() != bit.name,
                     qPrintable(QStringLiteral("%1: %2").arg(def.address.toString(), bit.name)));
    }
}

void TestDescriptionFile::movingCapErrorTextsInGerman()
{
    const ObjectDictionary &dict = resources::movingCapDictionary();
    const test::TextLanguage german(QStringLiteral("de"));
    QCOMPARE(dict.errorText(0x2220), QStringLiteral("Überstrom"));
    QCOMPARE(dict.errorText(0x7121),
             QStringLiteral("Blockade / Blockfahrt / Schleppfehler zu groß"));
    for (const quint32 code : { 0x2220, 0x3211, 0x3221, 0x4210, 0x4220, 0x5200, 0x7121, 0x7510,
                                0xFFF1, 0xFFF2, 0xFFF4, 0xFFF5 })
        QVERIFY2(dict.errorCode(code)->localTexts.contains(QStringLiteral("de")),
                 qPrintable(QString::number(code, 16)));
}

// What the editor shows as a description or error text names no source document and carries no
// note meant for the people who wrote the description.
void TestDescriptionFile::builtinTextsAreForUsers()
{
    static const QRegularExpression reference(
        QStringLiteral(R"(\[(seed|STD|EXT)\b|§|web footer|\.md\b|specs/)"),
        QRegularExpression::CaseInsensitiveOption);
    for (const QString &name : resources::builtinDescriptionNames()) {
        const auto dict = resources::builtinDescription(name);
        QVERIFY2(dict.ok(), qPrintable(name));
        for (const ObjectDef &def : dict.value().objects())
            QVERIFY2(!reference.match(def.description).hasMatch(),
                     qPrintable(name + QStringLiteral(": ") + def.description));
    }
}

void TestDescriptionFile::brokenFilesGiveClearErrors_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("mentions");
    const QByteArray head = R"({"format":"drivebench-device-description","version":1,)";
    QTest::newRow("not json") << QByteArray("{ nope") << "JSON error";
    QTest::newRow("foreign json") << QByteArray(R"({"hello":1})") << "not a drivebench";
    QTest::newRow("future version")
        << QByteArray(R"({"format":"drivebench-device-description","version":7})") << "version 7";
    QTest::newRow("bad index") << head + R"("objects":[{"index":"0x1FFFF","sub":0,"type":"U8"}]})"
                               << "bad index";
    QTest::newRow("bad type") << head + R"("objects":[{"index":"0x2000","sub":0,"type":"U9"}]})"
                              << "unknown type 'U9'";
    QTest::newRow("default out of range")
        << head + R"("objects":[{"index":"0x2000","sub":0,"type":"U8","default":300}]})"
        << "default";
    QTest::newRow("not a language")
        << head + R"("objects":[{"index":"0x2000","sub":0,"type":"U8","name_German":"x"}]})"
        << "\"German\" is not a language code";
    QTest::newRow("empty local name")
        << head + R"("objects":[{"index":"0x2000","sub":0,"type":"U8","object_de":""}]})"
        << "\"object_de\" must be a non-empty text";
    QTest::newRow("local value of no enum value")
        << head + R"("objects":[{"index":"0x2000","sub":0,"type":"U8","enum":{"0":"off"},
                                 "enum_de":{"1":"an"}}]})"
        << "\"enum_de\": 1 is not a value of \"enum\"";
    QTest::newRow("local values not an object")
        << head + R"("objects":[{"index":"0x2000","sub":0,"type":"U8","enum_de":"aus"}]})"
        << "\"enum_de\" must map values to texts";
    QTest::newRow("empty local unit")
        << head + R"("objects":[{"index":"0x2000","sub":0,"type":"U8","unit_de":""}]})"
        << "\"unit_de\" must be a non-empty text";
    QTest::newRow("empty local bit name")
        << head + R"("objects":[{"index":"0x2000","sub":0,"type":"U8",
                                 "bits":[{"bit":0,"name":"x","name_de":""}]}]})"
        << "bit #1: \"name_de\" must be a non-empty text";
    QTest::newRow("local text not a string")
        << head + R"("errors":[{"code":"0x2220","text":"x","text_de":5}]})"
        << "error #1: \"text_de\" must be a non-empty text";
}

void TestDescriptionFile::brokenFilesGiveClearErrors()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, mentions);
    const auto dict = parseJsonDescription(json, QStringLiteral("test.json"));
    QVERIFY(!dict.ok());
    QVERIFY2(dict.error().message().contains(mentions), qPrintable(dict.error().message()));
    QVERIFY(dict.error().message().contains(QLatin1String("test.json")));
}

void TestDescriptionFile::missingFileNamesThePath()
{
    const auto dict = loadJsonDescription(QStringLiteral("/nonexistent/x.json"));
    QCOMPARE(dict.error().kind(), Error::Kind::Io);
    QVERIFY(dict.error().message().contains(QLatin1String("/nonexistent/x.json")));
}

QTEST_GUILESS_MAIN(TestDescriptionFile)
#include "tst_descriptionfile.moc"
