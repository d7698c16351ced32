// Level 2: whether a node followed an NMT command, judged from its heartbeats (NmtAnswer) on a
// ScriptedCanBus: the expected state confirms, silence or another state within the node's
// consumer time is an error naming what was heard, a node never heard cannot confirm.
#include "canopen/nmtanswer.h"
#include "canopen/nodemonitor.h"
#include "scriptedcanbus.h"

#include <QtTest>

using namespace db;
using namespace db::canopen;
using db::test::ScriptedCanBus;

class TestNmtAnswer : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void expectedStates()
    {
        QCOMPARE(NmtAnswer::expectedState(NmtCommand::Start), NmtState::Operational);
        QCOMPARE(NmtAnswer::expectedState(NmtCommand::Stop), NmtState::Stopped);
        QCOMPARE(NmtAnswer::expectedState(NmtCommand::EnterPreOperational),
                 NmtState::PreOperational);
        QCOMPARE(NmtAnswer::expectedState(NmtCommand::ResetNode), NmtState::BootUp);
        QCOMPARE(NmtAnswer::expectedState(NmtCommand::ResetCommunication), NmtState::BootUp);
    }

    void heartbeatWithTheNewStateConfirms()
    {
        ScriptedCanBus bus;
        bus.open();
        NodeMonitor monitor(&bus);
        monitor.setConsumerTime(5, 200);
        bus.feed(0x705, "7F"); // pre-operational, heard before the command
        NmtAnswer answer(&bus, &monitor, NmtCommand::Start, 5);
        QSignalSpy finished(&answer, &NmtAnswer::finished);
        bus.feed(0x705, "7F"); // not yet
        QCOMPARE(finished.count(), 0);
        bus.feed(0x706, "05"); // another node
        QCOMPARE(finished.count(), 0);
        bus.feed(0x705, "05");
        QCOMPARE(finished.count(), 1);
        QVERIFY(!finished.first().first().value<Error>().isError());
        QVERIFY(answer.confirmed());
        QVERIFY(answer.note().isEmpty());
    }

    void resetIsConfirmedByBootUp()
    {
        ScriptedCanBus bus;
        bus.open();
        NodeMonitor monitor(&bus);
        bus.feed(0x705, "05");
        NmtAnswer answer(&bus, &monitor, NmtCommand::ResetNode, 5);
        QSignalSpy finished(&answer, &NmtAnswer::finished);
        bus.feed(0x705, "00");
        QCOMPARE(finished.count(), 1);
        QVERIFY(answer.confirmed());
    }

    void silenceIsNoAnswer()
    {
        ScriptedCanBus bus;
        bus.open();
        NodeMonitor monitor(&bus);
        monitor.setConsumerTime(5, 100);
        bus.feed(0x705, "7F");
        NmtAnswer answer(&bus, &monitor, NmtCommand::Start, 5);
        QSignalSpy finished(&answer, &NmtAnswer::finished);
        QVERIFY(finished.wait(2000));
        const Error error = finished.first().first().value<Error>();
        QCOMPARE(error.kind(), Error::Kind::Timeout);
        QVERIFY2(error.message().contains(QLatin1String("no answer"))
                     && error.message().contains(QLatin1String("100 ms")),
                 qPrintable(error.message()));
        QVERIFY(!answer.confirmed());
    }

    void anotherStateIsNamed()
    {
        ScriptedCanBus bus;
        bus.open();
        NodeMonitor monitor(&bus);
        monitor.setConsumerTime(5, 100);
        bus.feed(0x705, "7F");
        NmtAnswer answer(&bus, &monitor, NmtCommand::Stop, 5);
        QSignalSpy finished(&answer, &NmtAnswer::finished);
        bus.feed(0x705, "7F"); // still pre-operational
        QVERIFY(finished.wait(2000));
        const Error error = finished.first().first().value<Error>();
        QVERIFY2(error.message().contains(QLatin1String("did not follow"))
                     && error.message().contains(QLatin1String("pre-operational")),
                 qPrintable(error.message()));
    }

    void nodeNeverHeardCannotConfirm()
    {
        ScriptedCanBus bus;
        bus.open();
        NodeMonitor monitor(&bus);
        NmtAnswer answer(&bus, &monitor, NmtCommand::Start, 5);
        QSignalSpy finished(&answer, &NmtAnswer::finished);
        QVERIFY(finished.wait(1000));
        QVERIFY(!finished.first().first().value<Error>().isError());
        QVERIFY(!answer.confirmed());
        QVERIFY2(answer.note().contains(QLatin1String("no heartbeat")), qPrintable(answer.note()));
    }
};

QTEST_MAIN(TestNmtAnswer)
#include "tst_nmtanswer.moc"
