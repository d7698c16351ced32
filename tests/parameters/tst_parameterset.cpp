// ParameterSet: the text format (round trip, odd names, corrupt/truncated/foreign files),
// defaults from a description, and the comparison with its counts.
#include "core/printable.h"
#include "parameters/parameterset.h"

#include <QTemporaryDir>
#include <QTest>

using namespace db;

class TestParameterSet : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void roundTripKeepsEverything();
    void oddNamesSurvive_data();
    void oddNamesSurvive();
    void saveIsAtomicAndLoadReadsIt();
    void missingFileIsAnIoError();
    void badFilesGiveAClearError_data();
    void badFilesGiveAClearError();
    void insertKeepsAddressOrder();
    void defaultsTakeStorableObjectsWithADefault();
    void compareCountsEachStatus();
    void compareNormalisesValues();
    void compareThreeWays();

private:
    static ParameterSet sample();
    static ObjectDictionary dictionary();
};

ParameterSet TestParameterSet::sample()
{
    ParameterSet set;
    set.identity.vendorName = QStringLiteral("Fullmo GmbH");
    set.identity.vendorId = 0x53B;
    set.identity.productName = QStringLiteral("MovingCap ETH");
    set.identity.productCode = 0x15D;
    set.identity.revision = QStringLiteral("rev \"0\"");
    set.identity.descriptionFile = QStringLiteral(":/devices/movingcap_eth.json");
    set.identity.descriptionVersion = QStringLiteral("1");
    set.source = QStringLiteral("refgo://127.0.0.1:10001");
    set.created = QDateTime(QDate(2026, 11, 21), QTime(21, 0, 0, 250), Qt::UTC);
    set.insert({ { 0x6083, 0 },
                 QStringLiteral("Profile acceleration"),
                 DataType::Unsigned32,
                 QVariant::fromValue<qulonglong>(1000),
                 QStringLiteral("mm/s²") });
    set.insert({ { 0x607D, 1 },
                 QStringLiteral("Min position limit"),
                 DataType::Integer32,
                 QVariant::fromValue<qlonglong>(-2147483647),
                 QString() });
    set.insert({ { 0x2000, 1 },
                 QStringLiteral("Gain"),
                 DataType::Real32,
                 QVariant(double(0.1f)),
                 QString() });
    set.insert({ { 0x2000, 2 },
                 QStringLiteral("Label"),
                 DataType::VisibleString,
                 QVariant(QStringLiteral("a \"b\", c\\d")),
                 QString() });
    set.insert({ { 0x2000, 3 },
                 QStringLiteral("Blob"),
                 DataType::OctetString,
                 QVariant(QByteArray::fromHex("00ff10")),
                 QString() });
    set.insert(
        { { 0x2000, 4 }, QStringLiteral("Flag"), DataType::Boolean, QVariant(true), QString() });
    set.insert({ { 0x2000, 5 },
                 QStringLiteral("Empty"),
                 DataType::VisibleString,
                 QVariant(QString()),
                 QString() });
    return set;
}

ObjectDictionary TestParameterSet::dictionary()
{
    ObjectDictionary dict;
    auto add = [&](ObjectAddress a, const char *name, DataType type, bool storable, QVariant def) {
        ObjectDef d;
        d.address = a;
        d.name = QString::fromLatin1(name);
        d.type = type;
        d.storable = storable;
        d.defaultValue = def;
        dict.insert(d);
    };
    add({ 0x6083, 0 }, "Profile acceleration", DataType::Unsigned32, true, 1000);
    add({ 0x6084, 0 }, "Profile deceleration", DataType::Unsigned32, true, QVariant());
    add({ 0x6041, 0 }, "Statusword", DataType::Unsigned16, false, 0);
    add({ 0x6098, 0 }, "Homing method", DataType::Integer8, true, QStringLiteral("35"));
    add({ 0x1017, 0 }, "Heartbeat", DataType::Unsigned16, true, QStringLiteral("0x10"));
    return dict;
}

void TestParameterSet::roundTripKeepsEverything()
{
    const ParameterSet set = sample();
    const QByteArray text = set.serialize();
    QVERIFY(text.startsWith("# drivebench parameter set\nformat 1\n"));
    QVERIFY(text.endsWith("end\n"));
    const auto back = ParameterSet::parse(text, QStringLiteral("mem"));
    QVERIFY2(back, qPrintable(back.error().toString()));
    QCOMPARE(back->entries(), set.entries());
    QCOMPARE(back->identity.vendorName, set.identity.vendorName);
    QCOMPARE(back->identity.vendorId, set.identity.vendorId);
    QCOMPARE(back->identity.productName, set.identity.productName);
    QCOMPARE(back->identity.productCode, set.identity.productCode);
    QCOMPARE(back->identity.revision, set.identity.revision);
    QCOMPARE(back->identity.descriptionFile, set.identity.descriptionFile);
    QCOMPARE(back->identity.descriptionVersion, set.identity.descriptionVersion);
    QCOMPARE(back->source, set.source);
    QCOMPARE(back->created, set.created);
    // Sorted by address, one line per object: a changed value is a one-line diff.
    QCOMPARE(back->entries().first().address, ObjectAddress(0x2000, 1));
    QCOMPARE(back->serialize(), text);
}

void TestParameterSet::oddNamesSurvive_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("spaces") << QStringLiteral("IN1 Target velocity (Sollgeschwindigkeit)");
    QTest::newRow("comma") << QStringLiteral("a, b,c");
    QTest::newRow("quotes") << QStringLiteral("say \"hi\"");
    QTest::newRow("backslash") << QStringLiteral("C:\\path\\");
    QTest::newRow("newline") << QStringLiteral("two\nlines\r\ttab");
    QTest::newRow("hash") << QStringLiteral("# not a comment");
    QTest::newRow("unicode") << QStringLiteral("Drehmoment µ° – ok");
    QTest::newRow("empty") << QString();
    QTest::newRow("terminal controls") << QString(u"\x1b[2J\x1b[H\a\b\0\x7f OK"_qs);
    QTest::newRow("C1, bidi, separators") << QStringLiteral("\u009b2J \u202eKO\u2066 a\u2029b");
    QTest::newRow("escape-like text") << QStringLiteral("\\x1b \\u202e \\0");
}

void TestParameterSet::oddNamesSurvive()
{
    QFETCH(QString, name);
    ParameterSet set;
    set.insert(
        { { 0x3000, 1 }, name, DataType::VisibleString, QVariant(QStringLiteral("x")), name });
    const QByteArray text = set.serialize();
    QCOMPARE(text.count('\n'), 10); // nothing in a name can break a line
    // nor act on a terminal that shows the file
    QVERIFY2(isPrintable(QString::fromUtf8(text), LineBreaks::Keep), text.constData());
    const auto back = ParameterSet::parse(text, QStringLiteral("mem"));
    QVERIFY2(back, qPrintable(back.error().toString()));
    QCOMPARE(back->entries().first().name, name);
    QCOMPARE(back->entries().first().unit, name);
}

void TestParameterSet::saveIsAtomicAndLoadReadsIt()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("set.dbp"));
    QVERIFY(sample().save(path));
    const auto loaded = ParameterSet::load(path);
    QVERIFY2(loaded, qPrintable(loaded.error().toString()));
    QCOMPARE(loaded->entries(), sample().entries());
    // A directory in the way: the save fails with the path in the message.
    const auto refused = sample().save(dir.path());
    QVERIFY(!refused);
    QCOMPARE(refused.error().kind(), Error::Kind::Io);
    QVERIFY(refused.error().message().contains(dir.path()));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList { QStringLiteral("set.dbp") });
}

void TestParameterSet::missingFileIsAnIoError()
{
    const auto r = ParameterSet::load(QStringLiteral("/nonexistent/x.dbp"));
    QVERIFY(!r);
    QCOMPARE(r.error().kind(), Error::Kind::Io);
    QVERIFY(r.error().message().contains(QLatin1String("/nonexistent/x.dbp")));
}

void TestParameterSet::badFilesGiveAClearError_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("expected"); // "origin:line: <text>"
    const QByteArray good = sample().serialize();
    const QByteArray head = "# drivebench parameter set\nformat 1\n";
    QTest::newRow("empty") << QByteArray() << QStringLiteral("f.dbp: empty file");
    QTest::newRow("foreign ini") << QByteArray("[FileInfo]\nFileName=x.eds\n")
                                 << QStringLiteral("f.dbp:1: not a drivebench parameter set");
    QTest::newRow("foreign binary") << QByteArray("\x7f"
                                                  "ELF\x02\x01\x01\x00",
                                                  8)
                                    << QStringLiteral("f.dbp:1: not a drivebench parameter set");
    QTest::newRow("newer format") << QByteArray("# drivebench parameter set\nformat 2\n")
                                  << QStringLiteral("f.dbp:2: format 2 is newer");
    QTest::newRow("no format") << QByteArray("# drivebench parameter set\nentries 0\nend\n")
                               << QStringLiteral("f.dbp:2: expected 'format 1'");
    QTest::newRow("only magic") << QByteArray("# drivebench parameter set\n")
                                << QStringLiteral("truncated: no 'format' line");
    QTest::newRow("no entries line") << head + "vendor 0x1 \"x\"\n"
                                     << QStringLiteral("f.dbp:4: truncated: no 'entries' line");
    QTest::newRow("missing end") << good.left(good.lastIndexOf("end"))
                                 << QStringLiteral("truncated: no 'end' line");
    QTest::newRow("fewer objects") << head + "entries 2\n6083:0 \"A\" UNSIGNED32 5 \"\"\n"
                                   << QStringLiteral("'entries 2' but only 1 object lines");
    QTest::newRow("cut inside a line")
        << good.left(good.indexOf("\"Gain\"") + 3) << QStringLiteral("unterminated quoted string");
    QTest::newRow("end too early") << head + "entries 2\n6083:0 \"A\" UNSIGNED32 5 \"\"\nend\n"
                                   << QStringLiteral("f.dbp:5: expected an object line");
    QTest::newRow("bad value") << head + "entries 1\n6083:0 \"A\" UNSIGNED16 70000 \"\"\nend\n"
                               << QStringLiteral("f.dbp:4: 6083:0:");
    QTest::newRow("bad type") << head + "entries 1\n6083:0 \"A\" UNSIGNED99 1 \"\"\nend\n"
                              << QStringLiteral("f.dbp:4: unknown type 'UNSIGNED99'");
    QTest::newRow("bad address") << head + "entries 1\nxyz \"A\" UNSIGNED16 1 \"\"\nend\n"
                                 << QStringLiteral("f.dbp:4: bad address 'xyz'");
    QTest::newRow("duplicate") << head
            + "entries 2\n6083:0 \"A\" UNSIGNED16 1 \"\"\n6083:0 \"A\" UNSIGNED16 2 \"\"\nend\n"
                               << QStringLiteral("f.dbp:5: 6083:0 appears twice");
    QTest::newRow("unquoted name") << head + "entries 1\n6083:0 A UNSIGNED16 1 \"\"\nend\n"
                                   << QStringLiteral("f.dbp:4: expected an object line");
    QTest::newRow("text after end") << good + "6083:0 \"A\" UNSIGNED16 1 \"\"\n"
                                    << QStringLiteral("text after 'end'");
    QTest::newRow("unknown header") << head + "colour blue\n"
                                    << QStringLiteral("f.dbp:3: unknown header line 'colour'");
    QTest::newRow("bad escape") << head + "source \"a\\qb\"\n"
                                << QStringLiteral("f.dbp:3: unknown escape");
    QTest::newRow("short hex escape") << head + "source \"a\\x1\"\n"
                                      << QStringLiteral("f.dbp:3: '\\x' needs 2 hex digits");
    QTest::newRow("bad hex escape") << head + "source \"\\u12g4\"\n"
                                    << QStringLiteral("f.dbp:3: '\\u' needs 4 hex digits");
}

void TestParameterSet::badFilesGiveAClearError()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    const auto r = ParameterSet::parse(bytes, QStringLiteral("f.dbp"));
    QVERIFY(!r);
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QVERIFY2(r.error().message().startsWith(QLatin1String("f.dbp")),
             qPrintable(r.error().message()));
    QVERIFY2(r.error().message().contains(expected), qPrintable(r.error().message()));
}

void TestParameterSet::insertKeepsAddressOrder()
{
    ParameterSet set;
    for (const quint16 i : { 0x6084, 0x1017, 0x6083, 0x2000 })
        set.insert({ { i, 0 },
                     QString(),
                     DataType::Unsigned8,
                     QVariant::fromValue<qulonglong>(1),
                     QString() });
    set.insert({ { 0x6083, 0 },
                 QStringLiteral("again"),
                 DataType::Unsigned8,
                 QVariant::fromValue<qulonglong>(7),
                 QString() });
    QCOMPARE(set.size(), 4);
    QCOMPARE(set.addresses(),
             (QList<ObjectAddress> { { 0x1017, 0 }, { 0x2000, 0 }, { 0x6083, 0 }, { 0x6084, 0 } }));
    QCOMPARE(set.find({ 0x6083, 0 })->raw.toULongLong(), 7u);
    QVERIFY(set.remove({ 0x2000, 0 }));
    QVERIFY(!set.remove({ 0x2000, 0 }));
    QVERIFY(!set.contains({ 0x2000, 0 }));
}

void TestParameterSet::defaultsTakeStorableObjectsWithADefault()
{
    const ParameterSet d = ParameterSet::defaults(dictionary());
    QCOMPARE(d.addresses(), (QList<ObjectAddress> { { 0x1017, 0 }, { 0x6083, 0 }, { 0x6098, 0 } }));
    QCOMPARE(d.find({ 0x1017, 0 })->raw, QVariant::fromValue<qulonglong>(16));
    QCOMPARE(d.find({ 0x6098, 0 })->raw, QVariant::fromValue<qlonglong>(35));
    QCOMPARE(d.source, QStringLiteral("defaults"));
}

void TestParameterSet::compareCountsEachStatus()
{
    const ObjectDictionary dict = dictionary();
    ParameterSet device;
    ParameterSet file;
    auto u32 = [](quint32 v) {
        return QVariant::fromValue<qulonglong>(v);
    };
    device.insert({ { 0x6083, 0 }, QString(), DataType::Unsigned32, u32(1000), QString() });
    file.insert({ { 0x6083, 0 }, QString(), DataType::Unsigned32, u32(1000), QString() });
    device.insert({ { 0x6084, 0 }, QString(), DataType::Unsigned32, u32(500), QString() });
    file.insert({ { 0x6084, 0 }, QString(), DataType::Unsigned32, u32(900), QString() });
    device.insert({ { 0x1017, 0 }, QString(), DataType::Unsigned16, u32(100), QString() });
    file.insert(
        { { 0x2222, 1 }, QStringLiteral("Vendor thing"), DataType::Unsigned8, u32(3), QString() });
    const ParameterComparison c = compareParameterSets(
        { device, file }, { QStringLiteral("device"), QStringLiteral("file") }, &dict);
    QCOMPARE(c.rows.size(), 4);
    QCOMPARE(c.count(CompareStatus::Unchanged), 1);
    QCOMPARE(c.count(CompareStatus::Changed), 1);
    QCOMPARE(c.count(CompareStatus::Missing), 1);
    QCOMPARE(c.count(CompareStatus::Unknown), 1);
    QCOMPARE(c.differingCount(), 3);
    QVERIFY(!c.identical());
    QCOMPARE(c.countsText(), QStringLiteral("1 unchanged, 1 changed, 1 missing, 1 unknown"));
    const CompareRow &missing = c.rows.at(0); // 1017:0
    QCOMPARE(missing.status, CompareStatus::Missing);
    QCOMPARE(missing.name, QStringLiteral("Heartbeat"));
    QCOMPARE(missing.valueText(0), QStringLiteral("100"));
    QCOMPARE(missing.valueText(1), QStringLiteral("-"));
    const CompareRow &unknown = c.rows.at(1); // 2222:1
    QCOMPARE(unknown.status, CompareStatus::Unknown);
    QCOMPARE(unknown.name, QStringLiteral("Vendor thing"));
    QCOMPARE(c.rows.at(3).valueText(1, codec::TextFormat::Hex), QStringLiteral("0x00000384"));
    // Without a description nothing is unknown.
    const ParameterComparison plain = compareParameterSets({ device, file }, {}, nullptr);
    QCOMPARE(plain.count(CompareStatus::Unknown), 0);
    QCOMPARE(plain.count(CompareStatus::Missing), 2);
}

void TestParameterSet::compareNormalisesValues()
{
    const ObjectDictionary dict = dictionary();
    ParameterSet device;
    ParameterSet file;
    // The device answered 16 as an integer; the file came from a tool that wrote "0x10".
    device.insert({ { 0x1017, 0 },
                    QString(),
                    DataType::Unsigned16,
                    QVariant::fromValue<qulonglong>(16),
                    QString() });
    file.insert({ { 0x1017, 0 },
                  QString(),
                  DataType::Unsigned16,
                  QVariant(QStringLiteral("0x10")),
                  QString() });
    device.insert({ { 0x6098, 0 }, QString(), DataType::Integer8, QVariant(int(35)), QString() });
    file.insert({ { 0x6098, 0 },
                  QString(),
                  DataType::Integer64,
                  QVariant::fromValue<qulonglong>(35),
                  QString() });
    const auto c = compareParameterSets({ device, file }, {}, &dict);
    QCOMPARE(c.count(CompareStatus::Unchanged), 2);
    QVERIFY(c.identical());
    QCOMPARE(c.rows.at(0).values.at(1), QVariant::fromValue<qulonglong>(16));
}

void TestParameterSet::compareThreeWays()
{
    const ObjectDictionary dict = dictionary();
    const ParameterSet defaults = ParameterSet::defaults(dict);
    ParameterSet device = defaults;
    ParameterSet file = defaults;
    device.insert({ { 0x6083, 0 },
                    QString(),
                    DataType::Unsigned32,
                    QVariant::fromValue<qulonglong>(2000),
                    QString() });
    const auto c = compareParameterSets(
        { device, file, defaults },
        { QStringLiteral("device"), QStringLiteral("file"), QStringLiteral("defaults") }, &dict);
    QCOMPARE(c.rows.size(), 3);
    QCOMPARE(c.count(CompareStatus::Changed), 1);
    QCOMPARE(c.count(CompareStatus::Unchanged), 2);
    const CompareRow &row = c.rows.at(1);
    QCOMPARE(row.address, ObjectAddress(0x6083, 0));
    QCOMPARE(row.values.size(), 3);
    QCOMPARE(row.valueText(0), QStringLiteral("2000"));
    QCOMPARE(row.valueText(2), QStringLiteral("1000"));
}

QTEST_GUILESS_MAIN(TestParameterSet)
#include "tst_parameterset.moc"
