// No text meant for us reaches the user: every built-in description (names, descriptions, value
// texts, error texts, identity) and its DCF export are free of references to where a fact was
// found (source notes, seed and spec file names, errata, what a manual leaves out).
#include "description/dcfwriter.h"
#include "devices/bonfiglioli/acudescription.h"
#include "devices/nm17x/nm17xdescription.h"
#include "resources/builtindescriptions.h"

#include <QRegularExpression>
#include <QTest>

using namespace db;

namespace {

// Notes about the sources: "[seed ...]", seed files ("003_ea960187281f44d7.txt"), spec and
// manual files, errata, gaps of a manual, web-footer remarks, "RABBIT: ..." tags.
const QRegularExpression &developerText()
{
    static const QRegularExpression re(
        QStringLiteral(R"(\bseeds?\b|\d{3}_[0-9a-f]{16}|\.pdf\b|\.md\b|_objects\.csv|)"
                       R"(\bspec (?:App|section|§)|\berrata\b|\bnot stated\b|\btypo\b|)"
                       R"(web footer|^RABBIT:|\[(?:STD|EXT|GAP|CONFLICT|UNCERTAIN)\b|)"
                       R"(\bmanual rev|\bthe manual\b|manual's)"),
        QRegularExpression::CaseInsensitiveOption | QRegularExpression::MultilineOption);
    return re;
}

QList<std::pair<QString, ObjectDictionary>> builtins()
{
    QList<std::pair<QString, ObjectDictionary>> all;
    for (const QString &name : resources::builtinDescriptionNames()) {
        auto dict = resources::builtinDescription(name);
        if (dict)
            all.append({ name, dict.value() });
    }
    all.append({ QStringLiteral("ACTIVE Cube"), bonfiglioli::acuDictionary() });
    for (auto v : { nm17x::Variant::Nm170, nm17x::Variant::Nm172, nm17x::Variant::Nm174 })
        all.append({ nm17x::variantName(v), nm17x::dictionary(v) });
    return all;
}

QStringList textsOf(const ObjectDictionary &dict)
{
    QStringList texts { dict.identity.vendorName, dict.identity.productName, dict.identity.revision,
                        dict.identity.descriptionVersion };
    for (const ObjectDef &def : dict.objects()) {
        texts << def.name << def.objectName << def.description << def.unit;
        texts << def.enumeration.values();
        for (const BitField &bit : def.bitFields)
            texts << bit.name;
    }
    for (quint32 code = 0; code <= 0xFFFF; ++code) {
        if (const auto e = dict.errorCode(code))
            texts << e->name << e->text;
    }
    return texts;
}

} // namespace

class TestDescriptionTexts : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void theGrepFindsDeveloperText()
    {
        // The pattern itself: each of these was once in a description or an export.
        for (const char *text :
             { "[seed 003] acceleration", "see 003_ea960187281f44d7.txt", "Data type: not stated",
               "Shown as 'x' in web footer", "RABBIT: only 35.", "Manual's table says",
               "revision manual rev. 0", "(spec App. C)", "[EXT] Fullmo vendor ID" })
            QVERIFY2(developerText().match(QString::fromUtf8(text)).hasMatch(), text);
        QVERIFY(
            !developerText().match(QStringLiteral("Manual setup: set 3301h.01h = 3")).hasMatch());
    }

    void builtinDescriptionsHaveNone_data()
    {
        QTest::addColumn<int>("which");
        const auto all = builtins();
        for (int i = 0; i < all.size(); ++i)
            QTest::newRow(qPrintable(all.at(i).first)) << i;
    }

    void builtinDescriptionsHaveNone()
    {
        QFETCH(int, which);
        const ObjectDictionary dict = builtins().at(which).second;
        QVERIFY(dict.size() > 0);
        for (const QString &text : textsOf(dict)) {
            const auto match = developerText().match(text);
            QVERIFY2(!match.hasMatch(),
                     qPrintable(QStringLiteral("'%1' in: %2").arg(match.captured(), text)));
        }
    }

    void dcfExportsHaveNone_data() { builtinDescriptionsHaveNone_data(); }

    void dcfExportsHaveNone()
    {
        QFETCH(int, which);
        const ObjectDictionary dict = builtins().at(which).second;
        const QString dcf = QString::fromUtf8(dcfText(dict, {}, {}));
        QVERIFY(dcf.contains(QStringLiteral("[DeviceInfo]")));
        const auto match = developerText().match(dcf);
        QVERIFY2(
            !match.hasMatch(),
            qPrintable(match.captured() + QStringLiteral(" in the line: ")
                       + dcf.mid(dcf.lastIndexOf(QLatin1Char('\n'), match.capturedStart()), 200)));
        QVERIFY(!dcf.contains(QStringLiteral("ProductNumber=0x00000000")));
    }
};

QTEST_GUILESS_MAIN(TestDescriptionTexts)
#include "tst_descriptiontexts.moc"
