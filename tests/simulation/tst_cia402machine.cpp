#include "simulation/cia402machine.h"

#include <QTest>

using namespace db::sim;
using db::cia402::State;
using Ramp = Cia402Machine::StopRamp;

Q_DECLARE_METATYPE(db::cia402::State)
Q_DECLARE_METATYPE(db::sim::Cia402Machine::StopRamp)

namespace {
quint16 sw(const Cia402Machine &m)
{
    return m.statusword({});
}

Cia402Machine enabled()
{
    Cia402Machine m;
    m.writeControlword(0x06);
    m.writeControlword(0x07);
    m.writeControlword(0x0F);
    return m;
}
} // namespace

class TestCia402Machine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void startsInSwitchOnDisabled();
    void transitions_data();
    void transitions();
    void enableSequenceGivesManualStatuswords();
    void switchOnPlusEnableFromReadyIsTransitions3And4();
    void operationEnabledAddsTargetReachedAndMovingBits();
    void quickStopOptions_data();
    void quickStopOptions();
    void quickStopOption5And6ReEnableWithTransition16();
    void quickStopOption1DoesNotReEnable();
    void faultReactionThenFaultOnStop();
    void faultWithoutPowerGoesStraightToFault();
    void faultResetOnlyOnRisingEdgeOfBit7();
    void faultResetBlockedNeedsPowerCycle();
    void missingSoftwareEnableRefusesEverySwitchOn();
    void setPointEdgeReportsImmediateAndRelative();
    void setPointNeedsBit4Cleared();
    void haltToggleIsReported();
};

void TestCia402Machine::startsInSwitchOnDisabled()
{
    Cia402Machine m;
    QCOMPARE(m.state(), State::SwitchOnDisabled);
    QCOMPARE(sw(m), quint16(0x0040));
}

void TestCia402Machine::transitions_data()
{
    QTest::addColumn<QList<int>>("before");
    QTest::addColumn<int>("controlword");
    QTest::addColumn<State>("expected");
    const QList<int> rtso { 0x06 };
    const QList<int> so { 0x06, 0x07 };
    const QList<int> oe { 0x06, 0x07, 0x0F };
    QTest::newRow("2 shutdown") << QList<int> {} << 0x06 << State::ReadyToSwitchOn;
    QTest::newRow("SOD ignores enable operation")
        << QList<int> {} << 0x0F << State::SwitchOnDisabled;
    QTest::newRow("3 switch on") << rtso << 0x07 << State::SwitchedOn;
    QTest::newRow("4 enable operation") << so << 0x0F << State::OperationEnabled;
    QTest::newRow("5 disable operation") << oe << 0x07 << State::SwitchedOn;
    QTest::newRow("6 shutdown") << so << 0x06 << State::ReadyToSwitchOn;
    QTest::newRow("7 disable voltage") << rtso << 0x00 << State::SwitchOnDisabled;
    QTest::newRow("7 quick stop") << rtso << 0x02 << State::SwitchOnDisabled;
    QTest::newRow("8 shutdown") << oe << 0x06 << State::ReadyToSwitchOn;
    QTest::newRow("9 disable voltage") << oe << 0x00 << State::SwitchOnDisabled;
    QTest::newRow("10 disable voltage") << so << 0x00 << State::SwitchOnDisabled;
    QTest::newRow("10 quick stop") << so << 0x02 << State::SwitchOnDisabled;
    QTest::newRow("11 quick stop") << oe << 0x02 << State::QuickStopActive;
    QTest::newRow("12 disable voltage")
        << QList<int> { 0x06, 0x07, 0x0F, 0x02 } << 0x00 << State::SwitchOnDisabled;
    QTest::newRow("PP 31 keeps OE") << oe << 0x1F << State::OperationEnabled;
    QTest::newRow("PP 63 keeps OE") << oe << 0x3F << State::OperationEnabled;
}

void TestCia402Machine::transitions()
{
    QFETCH(QList<int>, before);
    QFETCH(int, controlword);
    QFETCH(State, expected);
    Cia402Machine m;
    for (int cw : before)
        m.writeControlword(quint16(cw));
    m.writeControlword(quint16(controlword));
    QCOMPARE(m.state(), expected);
}

void TestCia402Machine::enableSequenceGivesManualStatuswords()
{
    Cia402Machine m;
    QCOMPARE(sw(m), quint16(0x0040));
    auto e = m.writeControlword(0x06);
    QVERIFY(e.stateChanged);
    QCOMPARE(sw(m), quint16(0x0021));
    m.writeControlword(0x07);
    QCOMPARE(sw(m), quint16(0x0023));
    e = m.writeControlword(0x0F);
    QVERIFY(e.powerOn);
    QCOMPARE(sw(m), quint16(0x0027));
    e = m.writeControlword(0x00);
    QVERIFY(e.powerOff);
    QCOMPARE(sw(m), quint16(0x0040));
}

void TestCia402Machine::switchOnPlusEnableFromReadyIsTransitions3And4()
{
    Cia402Machine m;
    m.writeControlword(0x06);
    const auto e = m.writeControlword(0x0F);
    QCOMPARE(m.state(), State::OperationEnabled);
    QVERIFY(e.powerOn);
}

void TestCia402Machine::operationEnabledAddsTargetReachedAndMovingBits()
{
    const Cia402Machine m = enabled();
    QCOMPARE(m.statusword({ .targetReached = true }), quint16(0x0427));
    QCOMPARE(m.statusword({ .moving = true }), quint16(0x0127));
    QCOMPARE(m.statusword({ .warning = true }), quint16(0x00A7));
    QCOMPARE(m.statusword({ .internalLimit = true, .modeBit12 = true }), quint16(0x1827));
}

void TestCia402Machine::quickStopOptions_data()
{
    QTest::addColumn<int>("option");
    QTest::addColumn<Ramp>("ramp");
    QTest::addColumn<State>("afterStop");
    QTest::newRow("0 off at once") << 0 << Ramp::Immediate << State::SwitchOnDisabled;
    QTest::newRow("1 profile ramp, off")
        << 1 << Ramp::ProfileDeceleration << State::SwitchOnDisabled;
    QTest::newRow("2 quick stop ramp, off")
        << 2 << Ramp::QuickStopDeceleration << State::SwitchOnDisabled;
    QTest::newRow("5 profile ramp, stay")
        << 5 << Ramp::ProfileDeceleration << State::QuickStopActive;
    QTest::newRow("6 quick stop ramp, stay")
        << 6 << Ramp::QuickStopDeceleration << State::QuickStopActive;
}

void TestCia402Machine::quickStopOptions()
{
    QFETCH(int, option);
    QFETCH(Ramp, ramp);
    QFETCH(State, afterStop);
    Cia402Machine m = enabled();
    m.setQuickStopOption(option);
    const auto e = m.writeControlword(0x02);
    QCOMPARE(e.stop, ramp);
    if (option != 0) {
        QCOMPARE(m.state(), State::QuickStopActive);
        QCOMPARE(m.statusword({}), quint16(0x0007));
        QCOMPARE(m.statusword({ .moving = true }), quint16(0x0107));
        m.stopCompleted();
    } else {
        QVERIFY(e.powerOff);
    }
    QCOMPARE(m.state(), afterStop);
}

void TestCia402Machine::quickStopOption5And6ReEnableWithTransition16()
{
    for (int option : { 5, 6 }) {
        Cia402Machine m = enabled();
        m.setQuickStopOption(option);
        m.writeControlword(0x02);
        m.stopCompleted();
        m.writeControlword(0x0F);
        QCOMPARE(m.state(), State::OperationEnabled);
    }
}

void TestCia402Machine::quickStopOption1DoesNotReEnable()
{
    Cia402Machine m = enabled();
    m.setQuickStopOption(1);
    m.writeControlword(0x02);
    m.writeControlword(0x0F); // still braking: no transition 16 for option 1
    QCOMPARE(m.state(), State::QuickStopActive);
}

void TestCia402Machine::faultReactionThenFaultOnStop()
{
    Cia402Machine m = enabled();
    const auto e = m.raiseFault();
    QCOMPARE(m.state(), State::FaultReactionActive);
    QCOMPARE(e.stop, Ramp::QuickStopDeceleration);
    QCOMPARE(sw(m), quint16(0x000F));
    QVERIFY(!m.writeControlword(0x0F).stateChanged); // controlword ignored meanwhile
    const auto done = m.stopCompleted();
    QCOMPARE(m.state(), State::Fault);
    QVERIFY(done.powerOff);
    QCOMPARE(sw(m), quint16(0x0008));
    QCOMPARE(m.statusword({ .targetReached = true, .moving = true }), quint16(0x0008));
}

void TestCia402Machine::faultWithoutPowerGoesStraightToFault()
{
    Cia402Machine m;
    m.raiseFault();
    QCOMPARE(m.state(), State::Fault);
}

void TestCia402Machine::faultResetOnlyOnRisingEdgeOfBit7()
{
    Cia402Machine m;
    m.writeControlword(0x80); // bit 7 already high when the fault comes
    m.raiseFault();
    m.writeControlword(0x80);
    QCOMPARE(m.state(), State::Fault); // level, not an edge
    m.writeControlword(0x00);
    const auto e = m.writeControlword(0x80);
    QVERIFY(e.faultReset);
    QCOMPARE(m.state(), State::SwitchOnDisabled); // 15
}

void TestCia402Machine::faultResetBlockedNeedsPowerCycle()
{
    Cia402Machine m;
    m.setFaultResetBlocked(true);
    m.raiseFault();
    m.writeControlword(0x80);
    QCOMPARE(m.state(), State::Fault);
}

void TestCia402Machine::missingSoftwareEnableRefusesEverySwitchOn()
{
    Cia402Machine m;
    m.setSoftwareEnable(false);
    m.writeControlword(0x06);
    auto e = m.writeControlword(0x07);
    QVERIFY(e.softwareEnableMissing);
    QCOMPARE(m.state(), State::ReadyToSwitchOn);
    e = m.writeControlword(0x0F);
    QVERIFY(e.softwareEnableMissing); // again at the next attempt
    m.setSoftwareEnable(true);
    m.writeControlword(0x06);
    e = m.writeControlword(0x0F);
    QVERIFY(!e.softwareEnableMissing);
    QCOMPARE(m.state(), State::OperationEnabled);
}

void TestCia402Machine::setPointEdgeReportsImmediateAndRelative()
{
    Cia402Machine m = enabled();
    auto e = m.writeControlword(0x1F);
    QVERIFY(e.newSetPoint);
    QVERIFY(!e.changeImmediately);
    m.writeControlword(0x0F);
    e = m.writeControlword(0x3F);
    QVERIFY(e.newSetPoint);
    QVERIFY(e.changeImmediately);
    m.writeControlword(0x0F);
    e = m.writeControlword(0x5F);
    QVERIFY(e.relative);
}

void TestCia402Machine::setPointNeedsBit4Cleared()
{
    Cia402Machine m = enabled();
    QVERIFY(m.writeControlword(0x1F).newSetPoint);
    QVERIFY(!m.writeControlword(0x1F).newSetPoint);
    QVERIFY(!m.writeControlword(0x3F).newSetPoint);
}

void TestCia402Machine::haltToggleIsReported()
{
    Cia402Machine m = enabled();
    QVERIFY(m.writeControlword(0x10F).haltChanged);
    QVERIFY(m.halted());
    QVERIFY(m.writeControlword(0x0F).haltChanged);
    QVERIFY(!m.halted());
}

QTEST_GUILESS_MAIN(TestCia402Machine)
#include "tst_cia402machine.moc"
