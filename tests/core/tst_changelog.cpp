// The change log: entries from start to outcome, writes tracked by their reply, the "not stored"
// mark until a permanent store, and the CSV file.
#include "core/changelog.h"
#include "core/objectdictionary.h"
#include "fakeconnection.h"
#include "objectdefs.h"
#include "wait.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace db;
using db::test::FakeConnection;

namespace {

ObjectDictionary dictionary()
{
    ObjectDictionary d;
    ObjectDef acc = test::objectDef(0x6083, 0, DataType::Unsigned32, Access::ReadWrite);
    acc.name = QStringLiteral("Profile acceleration");
    d.insert(acc);
    return d;
}

} // namespace

class TestChangeLog : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void writeIsPendingUntilItsReplyFinishes()
    {
        FakeConnection c(QStringLiteral("fake://drive"));
        c.setDictionary(dictionary());
        c.setCapabilities(DeviceConnection::Capability::StoreNonVolatile);
        c.open();
        QTRY_VERIFY(c.isConnected());
        ChangeLog log;
        QSignalSpy added(&log, &ChangeLog::entryAdded);
        QSignalSpy changed(&log, &ChangeLog::entryChanged);
        Reply *reply = c.write({ 0x6083, 0 }, QVariant::fromValue<qulonglong>(2000));
        const std::unique_ptr<Reply> owned(reply); // the requester owns its reply
        const int id = log.track(
            ChangeLog::writeEntry(c, { 0x6083, 0 }, QStringLiteral("1000"), QStringLiteral("2000")),
            reply);
        QCOMPARE(added.count(), 1);
        const ChangeLog::Entry *e = log.find(id);
        QVERIFY(e);
        QCOMPARE(e->outcome, ChangeLog::Outcome::Pending);
        QCOMPARE(e->device, QStringLiteral("fake://drive"));
        QCOMPARE(e->object, QStringLiteral("6083:0 Profile acceleration"));
        QVERIFY(e->storable);
        QTRY_COMPARE(log.find(id)->outcome, ChangeLog::Outcome::Ok);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(log.unstoredCount(QStringLiteral("fake://drive")), 1);
        QCOMPARE(ChangeLog::summary(*log.find(id)),
                 QString(u"fake://drive: write 6083:0 Profile acceleration 1000 → 2000: ok"_qs));
    }

    void refusedWriteKeepsTheDevicesReason()
    {
        FakeConnection c(QStringLiteral("fake://drive"));
        c.setDictionary(dictionary());
        c.open();
        QTRY_VERIFY(c.isConnected());
        c.setFailure({ 0x6083, 0 },
                     Error(Error::Kind::DeviceError, QStringLiteral("value range exceeded")));
        ChangeLog log;
        const std::unique_ptr<Reply> reply(
            c.write({ 0x6083, 0 }, QVariant::fromValue<qulonglong>(9)));
        const int id = log.track(ChangeLog::writeEntry(c, { 0x6083, 0 }, {}, QStringLiteral("9")),
                                 reply.get());
        QTRY_COMPARE(log.find(id)->outcome, ChangeLog::Outcome::Failed);
        QVERIFY(log.find(id)->message.contains(QLatin1String("value range exceeded")));
        // Without a permanent store on the device nothing is "not stored"; a failure never is.
        QVERIFY(!log.find(id)->storable);
        QCOMPARE(log.unstoredCount(QStringLiteral("fake://drive")), 0);
    }

    void storeMarksOnlyThatDevicesWrites()
    {
        ChangeLog log;
        ChangeLog::Entry a;
        a.device = QStringLiteral("fake://a");
        a.storable = true;
        ChangeLog::Entry b = a;
        b.device = QStringLiteral("fake://b");
        const int ia = log.add(a);
        const int ib = log.add(b);
        ChangeLog::Entry ram = a;
        ram.storable = false;
        ram.workingMemoryOnly = true;
        const int ir = log.add(ram);
        for (int id : { ia, ib, ir })
            log.complete(id, Error());
        QCOMPARE(log.unstoredCount(QStringLiteral("fake://a")), 1);
        log.markStored(QStringLiteral("fake://a"));
        QVERIFY(log.find(ia)->stored);
        QVERIFY(!log.find(ib)->stored);
        QVERIFY(!log.find(ir)->stored);
        QCOMPARE(ChangeLog::storedText(*log.find(ia)), QStringLiteral("yes"));
        QCOMPARE(ChangeLog::storedText(*log.find(ib)), QStringLiteral("no"));
        QCOMPARE(ChangeLog::storedText(*log.find(ir)), QStringLiteral("RAM only"));
        // A finished entry keeps its outcome.
        log.complete(ia, Error(Error::Kind::Timeout, QStringLiteral("late")));
        QCOMPARE(log.find(ia)->outcome, ChangeLog::Outcome::Ok);
    }

    void replyDeletedUnfinishedLeavesNoPendingEntry()
    {
        ChangeLog log;
        auto *reply = new Reply(ObjectAddress { 0x6083, 0 });
        const int id = log.track({}, reply);
        delete reply;
        QCOMPARE(log.find(id)->outcome, ChangeLog::Outcome::Failed);
        const int none = log.track({}, nullptr);
        QCOMPARE(log.find(none)->outcome, ChangeLog::Outcome::Failed);
    }

    void oldEntriesAreDroppedAtTheLimit()
    {
        ChangeLog log;
        QSignalSpy removed(&log, &ChangeLog::entriesRemoved);
        int last = 0;
        for (int i = 0; i < ChangeLog::kMaxEntries + 3; ++i)
            last = log.add({});
        QCOMPARE(log.count(), ChangeLog::kMaxEntries);
        QCOMPARE(removed.count(), 3);
        QVERIFY(!log.find(1));
        QVERIFY(log.find(last));
        QCOMPARE(log.entries().first().id, 4);
    }

    void csvQuotesEveryField()
    {
        ChangeLog log;
        ChangeLog::Entry e;
        e.time = QDateTime(QDate(2026, 11, 26), QTime(16, 5, 7, 123), Qt::UTC);
        e.device = QStringLiteral("refgo://127.0.0.1");
        e.object = QStringLiteral("1008:0 Name, \"quoted\"");
        e.newValue = QStringLiteral("line1\nline2");
        e.storable = true;
        log.complete(log.add(e), Error());
        const QStringList lines = log.toCsv().split(QLatin1Char('\n'));
        QCOMPARE(
            lines.first(),
            QStringLiteral("time,device,action,object,old value,new value,result,message,stored"));
        QVERIFY2(lines.at(1).startsWith(
                     QStringLiteral("\"2026-11-26T16:05:07.123Z\",\"refgo://127.0.0.1\",\"write\","
                                    "\"1008:0 Name, \"\"quoted\"\"\",\"\",\"line1")),
                 qPrintable(lines.at(1)));
        QVERIFY(log.toCsv().contains(QStringLiteral("line2\",\"ok\",\"\",\"no\"\n")));
    }

    void saveIsAtomicAndNamesTheCause()
    {
        QTemporaryDir dir;
        ChangeLog log;
        log.add({});
        const QString path = dir.filePath(QStringLiteral("changes.csv"));
        QVERIFY(!log.saveCsv(path).isError());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(file.readAll()), log.toCsv());
        // A folder cannot be written as a file: the error names it, nothing is left behind.
        const Error e = log.saveCsv(dir.path());
        QVERIFY(e.isError());
        QCOMPARE(e.kind(), Error::Kind::Io);
        QVERIFY2(e.message().contains(QFileInfo(dir.path()).fileName()), qPrintable(e.message()));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files),
                 QStringList { QStringLiteral("changes.csv") });
    }
};

QTEST_GUILESS_MAIN(TestChangeLog)
#include "tst_changelog.moc"
