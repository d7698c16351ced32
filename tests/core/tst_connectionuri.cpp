#include "core/protocolregistry.h"

#include <QTest>

using namespace db;

namespace {

class NullConnection : public DeviceConnection
{
public:
    using DeviceConnection::DeviceConnection;
    QString protocolKey() const override { return QStringLiteral("null"); }

protected:
    void doOpen() override { }
    void doClose() override { }
    void doRead(Reply *, const ObjectDef *) override { }
    void doWrite(Reply *, const QVariant &, const ObjectDef *) override { }
};

ProtocolRegistry registry()
{
    ProtocolRegistry r;
    auto make = [](const ConnectionPlan &plan) -> Result<std::unique_ptr<DeviceConnection>> {
        return std::unique_ptr<DeviceConnection>(std::make_unique<NullConnection>(plan.uri));
    };
    r.add({ QStringLiteral("refgo"),
            QStringLiteral("refgo"),
            QStringLiteral("RefGo"),
            QStringLiteral("refgo://HOST[:PORT]"),
            10001,
            make,
            {},
            {} });
    r.add({ QStringLiteral("canopen+slcan"),
            QStringLiteral("canopen"),
            QStringLiteral("SLCAN"),
            QStringLiteral("canopen+slcan://HOST[:PORT]?node=N"),
            15001,
            make,
            {},
            {} });
    r.add({ QStringLiteral("canopen+socketcan"),
            QStringLiteral("canopen"),
            QStringLiteral("SocketCAN"),
            QStringLiteral("canopen+socketcan://IFACE?node=N"),
            -1,
            make,
            {},
            {} });
    r.add({ QStringLiteral("vabus"),
            QStringLiteral("vabus"),
            QStringLiteral("VABus"),
            QStringLiteral("vabus://HOST[:PORT]"),
            17220,
            make,
            {},
            {} });
    return r;
}

} // namespace

class TestConnectionUri : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void defaultPortsApply_data();
    void defaultPortsApply();
    void refusesBadUris_data();
    void refusesBadUris();
    void queryParameters();
    void registryMakesConnections();
};

void TestConnectionUri::defaultPortsApply_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("canonical");
    QTest::newRow("refgo default") << "refgo://192.168.2.150"
                                   << "refgo://192.168.2.150:10001";
    QTest::newRow("refgo port") << "refgo://127.0.0.1:4711"
                                << "refgo://127.0.0.1:4711";
    QTest::newRow("slcan default") << "canopen+slcan://192.168.2.150?node=50"
                                   << "canopen+slcan://192.168.2.150:15001?node=50";
    QTest::newRow("socketcan") << "canopen+socketcan://can0?node=5&bitrate=500000"
                               << "canopen+socketcan://can0?bitrate=500000&node=5";
    QTest::newRow("vabus default") << "vabus://10.0.0.1"
                                   << "vabus://10.0.0.1:17220";
    QTest::newRow("upper-case scheme") << "REFGO://localhost"
                                       << "refgo://localhost:10001";
    QTest::newRow("trailing slash") << "refgo://127.0.0.1/"
                                    << "refgo://127.0.0.1:10001";
}

void TestConnectionUri::defaultPortsApply()
{
    QFETCH(QString, text);
    QFETCH(QString, canonical);
    const auto uri = registry().parseUri(text);
    QVERIFY2(uri.ok(), qPrintable(uri.error().toString()));
    QCOMPARE(uri->toString(), canonical);
}

void TestConnectionUri::refusesBadUris_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("mentions");
    QTest::newRow("no scheme") << "192.168.2.150"
                               << "refgo://";
    QTest::newRow("unknown scheme") << "modbus://1.2.3.4"
                                    << "unknown protocol 'modbus'";
    QTest::newRow("no host") << "refgo://"
                             << "no valid host";
    QTest::newRow("bad port") << "refgo://1.2.3.4:99999"
                              << "99999";
    QTest::newRow("path") << "refgo://1.2.3.4/drive"
                          << "path";
}

void TestConnectionUri::refusesBadUris()
{
    QFETCH(QString, text);
    QFETCH(QString, mentions);
    const auto uri = registry().parseUri(text);
    QVERIFY(!uri.ok());
    QCOMPARE(uri.error().kind(), Error::Kind::InvalidArgument);
    QVERIFY2(uri.error().message().contains(mentions), qPrintable(uri.error().message()));
}

void TestConnectionUri::queryParameters()
{
    const auto uri = ConnectionUri::parse(QStringLiteral("canopen+virtualcan://can0?node=0x32"));
    QVERIFY(uri.ok());
    QCOMPARE(uri->queryInt(QStringLiteral("node"), 1, 127).value(), 50);
    const auto missing = uri->queryInt(QStringLiteral("bitrate"), 10000, 1000000);
    QVERIFY(!missing.ok());
    QVERIFY(missing.error().message().contains(QLatin1String("bitrate=(missing)")));
    const auto bad = ConnectionUri::parse(QStringLiteral("canopen+slcan://h?node=200"));
    QVERIFY(!bad->queryInt(QStringLiteral("node"), 1, 127).ok());
}

void TestConnectionUri::registryMakesConnections()
{
    const auto r = registry();
    auto conn = r.create(QStringLiteral("refgo://127.0.0.1"));
    QVERIFY(conn.ok());
    QCOMPARE(conn.value()->uri().port(), 10001);
    QCOMPARE(conn.value()->state(), DeviceConnection::State::Disconnected);
    QVERIFY(!r.create(QStringLiteral("nope://x")).ok());
    QCOMPARE(r.protocols().size(), 4);
}

QTEST_GUILESS_MAIN(TestConnectionUri)
#include "tst_connectionuri.moc"
