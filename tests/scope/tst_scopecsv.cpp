// Level 1: CSV export/import of recordings: exact round trip of values, times, gaps, scaling and
// metadata; time ranges; rows for channels sampled at different times; corrupt input with the
// line number; atomic file writes.
#include "core/printable.h"
#include "scope/csv.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace db;
using namespace db::scope;

namespace {

Recording sample()
{
    Recording rec;
    rec.device = QStringLiteral("refgo://127.0.0.1:10001");
    rec.startedAt = QDateTime(QDate(2026, 11, 21), QTime(21, 0, 0, 123), Qt::UTC);
    rec.mode = QStringLiteral("single");
    RecordedChannel pos;
    pos.info.id = QStringLiteral("6064:0");
    pos.info.address = { 0x6064, 0 };
    pos.info.name = QStringLiteral("Position actual value");
    pos.info.unit = QStringLiteral("inc");
    pos.info.device = rec.device;
    pos.info.sourceRateMs = 10;
    RecordedChannel cur;
    cur.info.id = QStringLiteral("6078:0");
    cur.info.address = { 0x6078, 0 };
    cur.info.name = QStringLiteral("Current; actual, value"); // separators in the name
    cur.info.unit = QStringLiteral("mA");
    cur.info.scale = 2.5;
    cur.info.offset = -1.25;
    cur.info.device = rec.device;
    pos.buffer = TraceBuffer(100);
    cur.buffer = TraceBuffer(100);
    for (int i = 0; i < 20; ++i) {
        pos.buffer.append(0.010 * i + 0.000000123, 1000 + i * 7);
        if (i == 12)
            cur.buffer.markLost(2);
        // Same time as the position on even samples, other times on odd ones.
        cur.buffer.append(i % 2 ? 0.010 * i + 0.0045 : 0.010 * i + 0.000000123, -3.25 * i);
    }
    pos.buffer.setCounters(5, 0);
    rec.channels = { pos, cur };
    rec.trigger.channel = 0;
    rec.trigger.kind = Trigger::Kind::RisingEdge;
    rec.trigger.level = 1050;
    rec.trigger.preTriggerS = 0.05;
    rec.trigger.postTriggerS = 0.15;
    rec.triggerTime = 0.08;
    return rec;
}

void compareBuffers(const TraceBuffer &a, const TraceBuffer &b)
{
    QCOMPARE(a.size(), b.size());
    for (qint64 i = 0; i < a.size(); ++i) {
        QCOMPARE(std::llround(a.time(i) * 1e9), std::llround(b.time(i) * 1e9));
        QCOMPARE(a.value(i), b.value(i));
        QCOMPARE(a.startsGap(i), b.startsGap(i));
    }
}

} // namespace

class TstScopeCsv : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void roundTrip()
    {
        const Recording rec = sample();
        const QByteArray text = csv::toCsv(rec);
        const auto back = csv::fromCsv(text);
        QVERIFY2(back.ok(), qPrintable(back.error().toString()));
        QCOMPARE(back->device, rec.device);
        QCOMPARE(back->startedAt, rec.startedAt);
        QCOMPARE(back->mode, rec.mode);
        QCOMPARE(back->trigger, rec.trigger);
        QCOMPARE(back->triggerTime, rec.triggerTime);
        QCOMPARE(back->channels.size(), 2);
        for (int c = 0; c < 2; ++c) {
            QCOMPARE(back->channels[c].info, rec.channels[c].info);
            compareBuffers(back->channels[c].buffer, rec.channels[c].buffer);
            QCOMPARE(back->channels[c].buffer.droppedOverwritten(),
                     rec.channels[c].buffer.droppedOverwritten());
            QCOMPARE(back->channels[c].buffer.lostAtSource(),
                     rec.channels[c].buffer.lostAtSource());
        }
        // Writing it again gives the same bytes.
        QCOMPARE(csv::toCsv(*back), text);
    }

    // Names and units come from device descriptions: their control characters neither break a
    // row nor act on a terminal showing the file, and the names still read back exactly.
    void controlCharactersInNames()
    {
        Recording rec = sample();
        rec.channels[0].info.name = QString(u"Pos\x1b[2J\rOK\n,\0\u009b\u202e"_qs);
        rec.channels[1].info.unit = QStringLiteral("m\u2029A\x07");
        rec.mode = QStringLiteral("single\x1b[31m");
        const QByteArray text = csv::toCsv(rec);
        QVERIFY2(isPrintable(QString::fromUtf8(text), LineBreaks::Keep), text.constData());
        QVERIFY2(
            text.contains("\ntime_s,\"6064:0 Pos\\x1b[2J\\rOK\\n,\\x00\\u009b\\u202e\",\"6078:0 "),
            text.constData());
        QCOMPARE(text.count('\n'), csv::toCsv(sample()).count('\n'));
        const auto back = csv::fromCsv(text);
        QVERIFY2(back.ok(), qPrintable(back.error().toString()));
        QCOMPARE(back->mode, rec.mode);
        for (int c = 0; c < 2; ++c)
            QCOMPARE(back->channels[c].info, rec.channels[c].info);
        QCOMPARE(csv::toCsv(*back), text);
    }

    void layoutOfRowsAndHeader()
    {
        const QByteArray text = csv::toCsv(sample());
        const QList<QByteArray> lines = text.split('\n');
        QCOMPARE(lines[0], QByteArray("# drivebench recording v1"));
        QVERIFY(text.contains(
            "# trigger: 6064:0,rising,1050; pre 0.05 s; post 0.15 s; at 0.080000000 s\n"));
        QVERIFY(text.contains("# channel: 6078:0; name: Current\\; actual, value; unit: mA; "
                              "scale: 2.5; offset: -1.25"));
        QVERIFY(text.contains("\ntime_s,6064:0 Position actual value,\"6078:0 Current; actual, "
                              "value\"\n"));
        // Shared time stamps share a row; the others leave the position cell empty.
        QVERIFY(text.contains("\n0.000000123,1000,-0\n")
                || text.contains("\n0.000000123,1000,0\n"));
        QVERIFY(text.contains("\n0.014500000,,-3.25\n"));
        // 20 shared/position rows + 10 current-only rows.
        const qsizetype header = lines.indexOf(
            QByteArray("time_s,6064:0 Position actual value,\"6078:0 Current; actual, value\""));
        QCOMPARE(lines.size() - header - 2, 30);
    }

    void timeRangeExport()
    {
        const auto back = csv::fromCsv(csv::toCsv(sample(), 0.05, 0.1));
        QVERIFY(back.ok());
        const TraceBuffer &pos = back->channels[0].buffer;
        QCOMPARE(pos.size(), 5); // 0.05 .. 0.09 (0.10 + 123 ns is outside)
        QVERIFY(pos.firstTime() >= 0.05 && pos.lastTime() <= 0.1);
    }

    // The same object from two devices, each with its own gaps: each reads back with its own.
    void sameObjectOfTwoDevicesKeepsItsGaps()
    {
        Recording rec = sample();
        RecordedChannel other = rec.channels[0];
        other.info.device = QStringLiteral("refgo://127.0.0.2:10001");
        other.buffer = TraceBuffer(100);
        RecordedChannel &own = rec.channels[0];
        own.buffer = TraceBuffer(100);
        for (int i = 0; i < 20; ++i) {
            if (i == 5)
                own.buffer.markLost(1);
            if (i == 9 || i == 15)
                other.buffer.markLost(3);
            own.buffer.append(0.010 * i, i);
            other.buffer.append(0.010 * i + 0.002, 100 + i);
        }
        rec.channels.append(other);
        const QByteArray text = csv::toCsv(rec);
        QVERIFY2(text.contains("# device-gaps: 6064:0; refgo://127.0.0.2:10001; "),
                 text.constData());
        const auto back = csv::fromCsv(text);
        QVERIFY2(back.ok(), qPrintable(back.error().toString()));
        QCOMPARE(back->channels.size(), 3);
        for (int c = 0; c < 3; ++c) {
            QCOMPARE(back->channels[c].info, rec.channels[c].info);
            compareBuffers(back->channels[c].buffer, rec.channels[c].buffer);
        }
        QCOMPARE(csv::toCsv(*back), text);
    }
    // A file written before gaps were kept per device: its "gaps" lines name the object, and a
    // channel of another device takes them when the file's device has no channel of that id.
    void gapsOfOlderFiles()
    {
        const QByteArray text = "# drivebench recording v1\n# device: refgo://a\n"
                                "# channel: 6064:0; name: P\n"
                                "# channel: 6078:0; name: I\n# channel-device: 6078:0; refgo://b\n"
                                "# gaps: 6064:0; 0.200000000\n# gaps: 6078:0; 0.300000000\n"
                                "time_s,6064:0 P,6078:0 I\n"
                                "0.1,1,10\n0.2,2,20\n0.3,3,30\n";
        const auto back = csv::fromCsv(text);
        QVERIFY2(back.ok(), qPrintable(back.error().toString()));
        const TraceBuffer &p = back->channels[0].buffer;
        const TraceBuffer &i = back->channels[1].buffer;
        QVERIFY(!p.startsGap(0) && p.startsGap(1) && !p.startsGap(2));
        QVERIFY(!i.startsGap(0) && !i.startsGap(1) && i.startsGap(2));
        QCOMPARE(back->channels[1].info.device, QStringLiteral("refgo://b"));
    }

    void corruptInputNamesTheLine_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("expected");
        const QByteArray head = "# drivebench recording v1\n# channel: 6064:0; name: P; unit: ; "
                                "scale: 1; offset: 0\ntime_s,6064:0 P\n";
        QTest::newRow("not ours") << QByteArray("a,b\n1,2\n") << "line 1:";
        QTest::newRow("no channels")
            << QByteArray("# drivebench recording v1\ntime_s,x\n") << "line 2: no '# channel:'";
        QTest::newRow("bad scale") << QByteArray("# drivebench recording v1\n# channel: 6064:0; "
                                                 "scale: zero\ntime_s,x\n")
                                   << "line 2: channel 6064:0: bad scale";
        QTest::newRow("missing header")
            << QByteArray("# drivebench recording v1\n# channel: 6064:0\n0.1,5\n")
            << "line 3: missing the column header";
        QTest::newRow("too many cells") << head + "0.1,1\n0.2,2,3\n"
                                        << "line 5: 3 cells";
        QTest::newRow("bad number") << head + "0.1,1\n0.2,x1\n"
                                    << "line 5: column 2 (6064:0)";
        QTest::newRow("bad time") << head + "abc,1\n"
                                  << "line 4: 'abc' is not a time";
        QTest::newRow("time back") << head + "0.2,1\n0.1,2\n"
                                   << "line 5: time goes back";
        QTest::newRow("gap line without times")
            << QByteArray("# drivebench recording v1\n# channel: 6064:0\n# gaps: 6064:0\n")
            << "line 3: bad gap line";
        QTest::newRow("bad gap time") << QByteArray("# drivebench recording v1\n# channel: 6064:0\n"
                                                    "# device-gaps: 6064:0; refgo://b; 1.x\n")
                                      << "line 3: bad gap time '1.x'";
        QTest::newRow("bad trigger")
            << QByteArray("# drivebench recording v1\n# trigger: 6041:0,bit3,set\n# channel: "
                          "6064:0\ntime_s,x\n")
            << "line 2: trigger '6041:0,bit3,set': 6041:0 is not one of";
    }
    void corruptInputNamesTheLine()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, expected);
        const auto rec = csv::fromCsv(text);
        QVERIFY(!rec.ok());
        QCOMPARE(rec.error().kind(), Error::Kind::Malformed);
        QVERIFY2(rec.error().message().startsWith(expected), qPrintable(rec.error().message()));
    }

    void fileRoundTripAndErrors()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString file = dir.filePath(QStringLiteral("trace.csv"));
        QVERIFY(csv::save(file, sample()).ok());
        const auto back = csv::load(file);
        QVERIFY(back.ok());
        QCOMPARE(back->channels.size(), 2);
        const auto missing = csv::load(dir.filePath(QStringLiteral("nothing.csv")));
        QCOMPARE(missing.error().kind(), Error::Kind::Io);
        QVERIFY(missing.error().message().contains(QStringLiteral("nothing.csv")));
        const auto unwritable =
            csv::save(dir.filePath(QStringLiteral("no/such/dir.csv")), sample());
        QCOMPARE(unwritable.error().kind(), Error::Kind::Io);
        // A failed save leaves the existing file untouched.
        const auto before = QFileInfo(file).size();
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner);
        const auto denied = csv::save(file, Recording());
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        if (denied.ok())
            QSKIP("running as root: directory permissions are not enforced");
        QCOMPARE(QFileInfo(file).size(), before);
    }
};

QTEST_GUILESS_MAIN(TstScopeCsv)
#include "tst_scopecsv.moc"
