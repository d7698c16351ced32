// Level 3: QtCanBus over Qt's virtualcan plugin (a fixed local TCP port: ctest LOCK virtualcan),
// and the clear errors for a missing plugin or interface. SocketCAN needs vcan0 (QSKIP here).

#include "transport/qtcanbus.h"

#include <QtTest>

using namespace db;

namespace {
constexpr int kWaitMs = 5000;
}

class TstQtCanBus : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void twoDevicesOnOneVirtualInterfaceSeeEachOther();
    void unknownPluginGivesClearError();
    void missingVirtualInterfaceIsNamed();
    void closeEmitsClosedWithoutError();
    void socketcanOnVcan0();
};

void TstQtCanBus::twoDevicesOnOneVirtualInterfaceSeeEachOther()
{
    QtCanBus a(QStringLiteral("virtualcan"), QStringLiteral("can0"));
    QtCanBus b(QStringLiteral("virtualcan"), QStringLiteral("can0"));
    QSignalSpy aOpened(&a, &CanBus::opened);
    QSignalSpy bOpened(&b, &CanBus::opened);
    QSignalSpy aClosed(&a, &CanBus::closed);
    a.open();
    b.open();
    QTRY_VERIFY_WITH_TIMEOUT(a.isOpen() && b.isOpen(), kWaitMs);
    if (!aClosed.isEmpty())
        QFAIL(qPrintable(aClosed.at(0).at(0).value<Error>().message()));
    QSignalSpy bReceived(&b, &CanBus::frameReceived);
    QSignalSpy aReceived(&a, &CanBus::frameReceived);
    QSignalSpy aSent(&a, &CanBus::frameSent);
    // Qt's virtualcan server forwards a frame only to the clients whose interface it has
    // registered, and it reads the two clients' sockets in any order: a frame sent as soon as
    // both report "open" can come before b's registration and reach nobody (seen once under the
    // sanitizers). So a sends until b has one, at most five times.
    int sent = 0;
    for (; sent < 5 && bReceived.isEmpty(); ++sent) {
        QVERIFY(a.send(QCanBusFrame(0x632, QByteArray::fromHex("4041600000000000"))));
        bReceived.wait(kWaitMs / 5);
    }
    QVERIFY(!bReceived.isEmpty());
    const auto frame = bReceived.at(0).at(0).value<QCanBusFrame>();
    QCOMPARE(frame.frameId(), 0x632u);
    QCOMPARE(frame.payload(), QByteArray::fromHex("4041600000000000"));
    QCOMPARE(aSent.size(), sent);
    QVERIFY(b.send(QCanBusFrame(0x5B2, QByteArray::fromHex("4B41600027040000"))));
    QVERIFY(aReceived.wait(kWaitMs));
    QCOMPARE(aReceived.at(0).at(0).value<QCanBusFrame>().frameId(), 0x5B2u);
}

void TstQtCanBus::unknownPluginGivesClearError()
{
    QtCanBus bus(QStringLiteral("nosuchplugin"), QStringLiteral("can7"));
    QSignalSpy closed(&bus, &CanBus::closed);
    bus.open();
    QCOMPARE(closed.size(), 0); // reported from the event loop, not inside open()
    QVERIFY(closed.wait(kWaitMs));
    const auto error = closed.at(0).at(0).value<Error>();
    QCOMPARE(error.kind(), Error::Kind::NotSupported);
    QVERIFY2(error.message().contains(QLatin1String("nosuchplugin")), qPrintable(error.message()));
    QVERIFY2(error.message().contains(QLatin1String("can7")), qPrintable(error.message()));
    QVERIFY2(error.message().contains(QLatin1String("virtualcan")), qPrintable(error.message()));
    QVERIFY(!bus.isOpen());
    QVERIFY(QtCanBus::availablePlugins().contains(QStringLiteral("virtualcan")));
}

void TstQtCanBus::missingVirtualInterfaceIsNamed()
{
    // virtualcan only logs a name it does not know and would open its first channel instead.
    const QStringList available = QtCanBus::availableInterfaces(QStringLiteral("virtualcan"));
    QVERIFY(!available.isEmpty());
    const auto checked =
        QtCanBus::checkInterface(QStringLiteral("virtualcan"), QStringLiteral("nosuchif"));
    QVERIFY(!checked);
    QCOMPARE(checked.error().kind(), Error::Kind::HostNotFound);
    QVERIFY(QtCanBus::checkInterface(QStringLiteral("virtualcan"), available.first()));

    QtCanBus bus(QStringLiteral("virtualcan"), QStringLiteral("nosuchif"));
    QSignalSpy closed(&bus, &CanBus::closed);
    QSignalSpy opened(&bus, &CanBus::opened);
    bus.open();
    QVERIFY(closed.wait(kWaitMs));
    QCOMPARE(opened.size(), 0);
    const auto error = closed.at(0).at(0).value<Error>();
    QCOMPARE(error.kind(), Error::Kind::HostNotFound);
    const QString text = error.message();
    QVERIFY2(text.contains(QLatin1String("'nosuchif'")), qPrintable(text));
    QVERIFY2(text.contains(QLatin1String("virtualcan")), qPrintable(text));
    for (const QString &name : available)
        QVERIFY2(text.contains(name), qPrintable(text)); // what the user can take instead
}

void TstQtCanBus::closeEmitsClosedWithoutError()
{
    QtCanBus bus(QStringLiteral("virtualcan"), QStringLiteral("can1"));
    QSignalSpy closed(&bus, &CanBus::closed);
    bus.open();
    QTRY_VERIFY_WITH_TIMEOUT(bus.isOpen(), kWaitMs);
    bus.close();
    QTRY_COMPARE_WITH_TIMEOUT(closed.size(), 1, kWaitMs);
    QVERIFY(!closed.at(0).at(0).value<Error>().isError());
    QVERIFY(!bus.send(QCanBusFrame(0x1, QByteArray("x"))));
}

void TstQtCanBus::socketcanOnVcan0()
{
    if (!QtCanBus::availableInterfaces(QStringLiteral("socketcan"))
             .contains(QStringLiteral("vcan0")))
        QSKIP("no vcan0 (SocketCAN) on this machine");
    QtCanBus bus(QStringLiteral("socketcan"), QStringLiteral("vcan0"));
    bus.open();
    QTRY_VERIFY_WITH_TIMEOUT(bus.isOpen(), kWaitMs);
    QVERIFY(bus.send(QCanBusFrame(0x000, QByteArray::fromHex("0132"))));
}

QTEST_GUILESS_MAIN(TstQtCanBus)
#include "tst_qtcanbus.moc"
