// The DeviceConnection base: checks before anything reaches the protocol, and pending replies
// that fail when the link goes away.
#include "core/deviceconnection.h"

#include <QSignalSpy>
#include <QTest>

using namespace db;

namespace {

class HoldingConnection : public DeviceConnection
{
public:
    using DeviceConnection::DeviceConnection;
    QString protocolKey() const override { return QStringLiteral("test"); }
    QList<QPointer<Reply>> held;
    QList<QVariant> written;
    void drop(const Error &e) { setState(State::Disconnected, e); }

protected:
    void doOpen() override { setState(State::Connected); }
    void doClose() override { setState(State::Disconnected); }
    void doRead(Reply *reply, const ObjectDef *) override { held.append(reply); }
    void doWrite(Reply *reply, const QVariant &raw, const ObjectDef *) override
    {
        written.append(raw);
        held.append(reply);
    }
};

ObjectDictionary dictionary()
{
    ObjectDictionary dict;
    ObjectDef sw;
    sw.address = ObjectAddress(0x6041, 0);
    sw.name = QStringLiteral("Statusword");
    sw.type = DataType::Unsigned16;
    sw.access = Access::ReadOnly;
    dict.insert(sw);
    ObjectDef acc;
    acc.address = ObjectAddress(0x6083, 0);
    acc.name = QStringLiteral("Profile acceleration");
    acc.type = DataType::Unsigned32;
    acc.minimum = QVariant::fromValue(1ULL);
    acc.maximum = QVariant::fromValue(20000ULL);
    dict.insert(acc);
    ObjectDef save;
    save.address = ObjectAddress(0x1010, 1);
    save.name = QStringLiteral("Store parameters");
    save.access = Access::WriteOnly;
    dict.insert(save);
    return dict;
}

Error kindOf(Reply *reply)
{
    QSignalSpy spy(reply, &Reply::finished);
    if (!reply->isFinished() || spy.isEmpty())
        spy.wait(1000);
    const Error e = reply->error();
    delete reply;
    return e;
}

} // namespace

class TestDeviceConnection : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void requestsWhileDisconnectedFail();
    void writeToReadOnlyObjectNeverReachesTheDevice();
    void readOfWriteOnlyObjectIsRefused();
    void writeOutsideTheObjectRangeIsRefused();
    void writeIsNormalisedToTheObjectType();
    void unknownObjectsPassThrough();
    void pendingRepliesFailWhenTheLinkDrops();
    void closeCancelsPendingReplies();
};

void TestDeviceConnection::requestsWhileDisconnectedFail()
{
    HoldingConnection conn(ConnectionUri::parse(QStringLiteral("test://x")).value());
    QCOMPARE(kindOf(conn.read(ObjectAddress(0x6041, 0))).kind(), Error::Kind::Disconnected);
    QCOMPARE(kindOf(conn.write(ObjectAddress(0x6083, 0), 5)).kind(), Error::Kind::Disconnected);
}

void TestDeviceConnection::writeToReadOnlyObjectNeverReachesTheDevice()
{
    HoldingConnection conn(ConnectionUri::parse(QStringLiteral("test://x")).value());
    conn.setDictionary(dictionary());
    conn.open();
    const Error e = kindOf(conn.write(ObjectAddress(0x6041, 0), 6));
    QCOMPARE(e.kind(), Error::Kind::AccessDenied);
    QVERIFY(e.message().contains(QLatin1String("Statusword")));
    QVERIFY(conn.written.isEmpty());
}

void TestDeviceConnection::readOfWriteOnlyObjectIsRefused()
{
    HoldingConnection conn(ConnectionUri::parse(QStringLiteral("test://x")).value());
    conn.setDictionary(dictionary());
    conn.open();
    QCOMPARE(kindOf(conn.read(ObjectAddress(0x1010, 1))).kind(), Error::Kind::AccessDenied);
    QVERIFY(conn.held.isEmpty());
}

void TestDeviceConnection::writeOutsideTheObjectRangeIsRefused()
{
    HoldingConnection conn(ConnectionUri::parse(QStringLiteral("test://x")).value());
    conn.setDictionary(dictionary());
    conn.open();
    QCOMPARE(kindOf(conn.write(ObjectAddress(0x6083, 0), 0)).kind(), Error::Kind::OutOfRange);
    QCOMPARE(kindOf(conn.write(ObjectAddress(0x6083, 0), -5)).kind(), Error::Kind::OutOfRange);
    QVERIFY(conn.written.isEmpty());
}

void TestDeviceConnection::writeIsNormalisedToTheObjectType()
{
    HoldingConnection conn(ConnectionUri::parse(QStringLiteral("test://x")).value());
    conn.setDictionary(dictionary());
    conn.open();
    Reply *reply = conn.write(ObjectAddress(0x6083, 0), QStringLiteral("0x3E8"));
    QCOMPARE(conn.written.size(), 1);
    QCOMPARE(conn.written.first(), QVariant::fromValue(1000ULL));
    delete reply;
}

void TestDeviceConnection::unknownObjectsPassThrough()
{
    HoldingConnection conn(ConnectionUri::parse(QStringLiteral("test://x")).value());
    conn.setDictionary(dictionary());
    conn.open();
    delete conn.write(ObjectAddress(0x2000, 3), -7);
    delete conn.read(ObjectAddress(0x2000, 3));
    QCOMPARE(conn.written.size(), 1);
    QCOMPARE(conn.written.first().toInt(), -7);
}

void TestDeviceConnection::pendingRepliesFailWhenTheLinkDrops()
{
    HoldingConnection conn(ConnectionUri::parse(QStringLiteral("test://x")).value());
    conn.open();
    Reply *a = conn.read(ObjectAddress(0x6041, 0));
    Reply *b = conn.read(ObjectAddress(0x6064, 0));
    QSignalSpy errors(&conn, &DeviceConnection::errorOccurred);
    conn.drop(Error(Error::Kind::Disconnected, QStringLiteral("peer closed")));
    QCOMPARE(errors.count(), 1);
    QCOMPARE(conn.state(), DeviceConnection::State::Disconnected);
    QCOMPARE(conn.lastError().message(), QStringLiteral("peer closed"));
    QCOMPARE(kindOf(a).message(), QStringLiteral("peer closed"));
    QCOMPARE(kindOf(b).kind(), Error::Kind::Disconnected);
}

void TestDeviceConnection::closeCancelsPendingReplies()
{
    HoldingConnection conn(ConnectionUri::parse(QStringLiteral("test://x")).value());
    conn.open();
    Reply *a = conn.read(ObjectAddress(0x6041, 0));
    conn.close();
    QCOMPARE(kindOf(a).kind(), Error::Kind::Cancelled);
    QCOMPARE(conn.state(), DeviceConnection::State::Disconnected);
}

QTEST_GUILESS_MAIN(TestDeviceConnection)
#include "tst_deviceconnection.moc"
